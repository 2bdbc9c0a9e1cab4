// Kept for includes written before session 11: the segment geometry of every vendor is one type now,
// motion::SegmentGeometry<D> (segment_geometry.hpp); PathSegmentGeometry and SpaceSegment are its D = 4 and D = 6.
#pragma once

#include "servobench/motion/segment_geometry.hpp"
