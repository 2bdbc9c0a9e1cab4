// Coordinated paths: segment geometry, feed profile and coordinate systems. Manual files in ../shared/seeds/:
// GT = 000_0c49d4aa9b235bd5.txt (digest gt.md §4, §9), GE = 001_b26ef06a365efe59.txt (ge.md §4, §8),
// GUC = 002_b2237d67fd2eb602.txt (guc-ecat.md §2.1-2.4, §6.1-6.3), iDEABOX = 003_2c62cffc310de7fb.txt.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "servobench/motion/coord_system.hpp"
#include "servobench/motion/path_feed.hpp"
#include "servobench/motion/path_segment.hpp"

namespace sm = servobench::motion;
using G = sm::PathSegmentGeometry;
using P = sm::CrdPoint;

namespace {
constexpr double kPi = 3.14159265358979323846;

int gt_code_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const sm::PathGeometryError& e) {
    return e.gt_code();
  }
  return 0;
}
}  // namespace

TEST(PathGeometry, GtTV38_GeT6_ArcByCentreAndAngle) {
  // GT L1899-1921 (TV38), GE L1595-1637 (T6): from (10, 10), ArcXY(0, 0, 123): r = 14.1421, end (-13.833, 2.940).
  const G g = G::arc_center_angle({10, 10, 0, 0}, 2, sm::ArcPlane::XY, 0, 0, 123);
  EXPECT_NEAR(g.radius(), std::sqrt(200.0), 1e-12);
  EXPECT_NEAR(g.end()[0], -13.833, 1e-3);
  EXPECT_NEAR(g.end()[1], 2.940, 1e-3);
  EXPECT_NEAR(g.length(), std::sqrt(200.0) * 123 * kPi / 180, 1e-9);
  EXPECT_NEAR(g.length(), 30.36, 0.01);
  // CCW: halfway the point is at 45 + 61.5 degrees.
  const P mid = g.point_at(g.length() / 2);
  EXPECT_NEAR(std::atan2(mid[1], mid[0]) * 180 / kPi, 106.5, 1e-9);
}

TEST(PathGeometry, GeT17_T20_HalfCircleInEachPlane) {
  // GE L3448-3465 (T17), L3529-3543 / L3603-3617 (T20): from the origin, Arc..(40000, 30000, 180): r = 50000,
  // end (80000, 60000) in the plane's own coordinates, length 157079.6.
  const sm::ArcPlane planes[] = {sm::ArcPlane::XY, sm::ArcPlane::YZ, sm::ArcPlane::ZX};
  for (auto pl : planes) {
    const G g = G::arc_center_angle({0, 0, 0, 0}, 3, pl, 40000, 30000, 180);
    const auto a = static_cast<std::size_t>(sm::plane_axis(pl, 0)), b = static_cast<std::size_t>(sm::plane_axis(pl, 1));
    EXPECT_NEAR(g.end()[a], 80000, 1e-6) << sm::to_string(pl);
    EXPECT_NEAR(g.end()[b], 60000, 1e-6);
    EXPECT_NEAR(g.length(), 50000 * kPi, 1e-6);
    // The normal coordinate stays put and the sweep is CCW about +normal (right-hand rule, GE L1481-1486).
    EXPECT_EQ(g.end()[static_cast<std::size_t>(sm::plane_axis(pl, 2))], 0.0);
    EXPECT_GT(g.sweep_rad(), 0.0);
  }
}

TEST(PathGeometry, RightHandRuleInEveryPlane) {
  // Positive = CCW seen from the positive third axis: XY x->y, YZ y->z, ZX z->x (GT L1793, GUC L883-886).
  const G xy = G::arc_center_angle({1, 0, 0, 0}, 3, sm::ArcPlane::XY, 0, 0, 90);
  EXPECT_NEAR(xy.end()[1], 1, 1e-12);
  const G yz = G::arc_center_angle({0, 1, 0, 0}, 3, sm::ArcPlane::YZ, 0, 0, 90);
  EXPECT_NEAR(yz.end()[2], 1, 1e-12);
  const G zx = G::arc_center_angle({0, 0, 1, 0}, 3, sm::ArcPlane::ZX, 0, 0, 90);
  EXPECT_NEAR(zx.end()[0], 1, 1e-12);
  // The tangent at the start of a CCW arc is the normal crossed with the radius.
  EXPECT_NEAR(zx.tangent_at(0)[0], 1, 1e-12);
}

TEST(PathGeometry, GeT18_T19_EndPointAndRadius) {
  // GE L3490-3505 (T18): from (0,0), ArcXYP(40000, 0, 20000, -1): a CW semicircle about (20000, 0) through
  // (20000, +20000). T19 (L3567-3581, L3642-3656): the same in YZ and ZX plane coordinates.
  for (auto pl : {sm::ArcPlane::XY, sm::ArcPlane::YZ, sm::ArcPlane::ZX}) {
    P end{0, 0, 0, 0};
    end[static_cast<std::size_t>(sm::plane_axis(pl, 0))] = 40000;
    const G g = G::arc_end_radius({0, 0, 0, 0}, end, 3, pl, 20000, false);
    const P mid = g.point_at(g.length() / 2);
    EXPECT_NEAR(mid[static_cast<std::size_t>(sm::plane_axis(pl, 0))], 20000, 1e-6);
    EXPECT_NEAR(mid[static_cast<std::size_t>(sm::plane_axis(pl, 1))], 20000, 1e-6);
    EXPECT_NEAR(g.sweep_rad(), -kPi, 1e-12);
  }
  // Chord > diameter: return 5 (GE L280-282); radius 0 or chord 0: return 2.
  EXPECT_EQ(gt_code_of([] { G::arc_end_radius({0, 0, 0, 0}, {40001, 0, 0, 0}, 2, sm::ArcPlane::XY, 20000, true); }), 5);
  EXPECT_EQ(gt_code_of([] { G::arc_end_radius({0, 0, 0, 0}, {1, 0, 0, 0}, 2, sm::ArcPlane::XY, 0, true); }), 2);
  EXPECT_EQ(gt_code_of([] { G::arc_end_radius({5, 5, 0, 0}, {5, 5, 0, 0}, 2, sm::ArcPlane::XY, 10, true); }), 2);
}

TEST(PathGeometry, GucCircleProgramArcs) {
  // GUC L857-875 (guc-ecat.md §6.3), iDEABOX Ex 4-5 L1448-1592: the centre form with start = end is a full
  // CW circle of R 100000; the radius form R = +200000 CCW to (0, 200000) is the 90 deg arc about the origin
  // (R = -200000 gives the 270 deg one about (200000, 200000)).
  const G full = G::arc_center_offset({200000, 0, 0, 0}, {200000, 0, 0, 0}, 2, sm::ArcPlane::XY, -100000, 0, false);
  EXPECT_NEAR(full.length(), 628318.53, 0.01);
  EXPECT_NEAR(full.sweep_rad(), -2 * kPi, 1e-15);
  EXPECT_NEAR(full.point_at(full.length() / 4)[1], -100000, 1e-6);  // CW: a quarter turn later it is below the centre
  const G quarter = G::arc_end_radius({200000, 0, 0, 0}, {0, 200000, 0, 0}, 2, sm::ArcPlane::XY, 200000, true);
  EXPECT_NEAR(quarter.center(0), 0, 1e-6);
  EXPECT_NEAR(quarter.center(1), 0, 1e-6);
  EXPECT_NEAR(quarter.length(), 314159.27, 0.01);
  const G major = G::arc_end_radius({200000, 0, 0, 0}, {0, 200000, 0, 0}, 2, sm::ArcPlane::XY, -200000, true);
  EXPECT_NEAR(major.center(0), 200000, 1e-6);
  EXPECT_NEAR(major.center(1), 200000, 1e-6);
  EXPECT_NEAR(major.sweep_rad(), 1.5 * kPi, 1e-12);
  // An end point off the circle: return 7 on these cards (GUC L906), GT/GE code 5.
  EXPECT_EQ(gt_code_of([] { G::arc_center_offset({0, 0, 0, 0}, {300, 0, 0, 0}, 2, sm::ArcPlane::XY, 100, 0, true); }), 5);
}

TEST(PathGeometry, GtTV39_GeT21_FullCircleByAngle) {
  // GT L3348-3357 (TV39), GE L4037-4062 (T21): ArcXY(2345, 6789, 360) from (1234, 5678): r = 1571.19, back to
  // the start, length 9872.1.
  const G g = G::arc_center_angle({1234, 5678, 9013, 0}, 3, sm::ArcPlane::XY, 2345, 6789, 360);
  EXPECT_NEAR(g.radius(), 1571.19, 0.01);
  EXPECT_EQ(g.end()[0], 1234);
  EXPECT_EQ(g.end()[1], 5678);
  EXPECT_NEAR(g.length(), 9872.1, 0.05);
}

TEST(PathGeometry, HelixAndCurvature) {
  // A helix: the XY arc with Z rising 100 per turn; length sqrt((2 pi r)^2 + 100^2), curvature radius (r^2+c^2)/r.
  const double r = 50, h = 100;
  const G g = G::arc_center_angle({r, 0, 0, 0}, 3, sm::ArcPlane::XY, 0, 0, 360, {0, 0, h, 0});
  EXPECT_NEAR(g.length(), std::hypot(2 * kPi * r, h), 1e-9);
  EXPECT_NEAR(g.end()[2], h, 1e-12);
  const double c = h / (2 * kPi);
  EXPECT_NEAR(g.curvature_radius(), (r * r + c * c) / r, 1e-9);
  EXPECT_NEAR(g.point_at(g.length() / 2)[2], h / 2, 1e-9);
  // Unit tangent, and consistent with the difference quotient of the points.
  const double s = 0.3 * g.length(), ds = 1e-4;
  const P a = g.point_at(s - ds), b = g.point_at(s + ds), t = g.tangent_at(s);
  double dot = 0, norm = 0;
  for (std::size_t k = 0; k < 4; ++k) dot += t[k] * (b[k] - a[k]) / (2 * ds), norm += t[k] * t[k];
  EXPECT_NEAR(norm, 1, 1e-12);
  EXPECT_NEAR(dot, 1, 1e-8);
}

TEST(PathGeometry, LinesAndErrors) {
  const G l = G::line({0, 0, 0, 0}, {12945, 58372, 65473, 0}, 3);  // GE L4988-5003 (T26): 88 666 pulse
  EXPECT_NEAR(l.length(), 88666, 1);
  EXPECT_EQ(gt_code_of([] { G::line({1, 2, 0, 0}, {1, 2, 0, 0}, 2); }), 3);  // GT L401: return 3
  EXPECT_EQ(gt_code_of([] { G::arc_center_angle({0, 0, 0, 0}, 2, sm::ArcPlane::XY, 0, 0, 90); }), 2);
  EXPECT_THROW(G::arc_center_angle({1, 0, 0, 0}, 2, sm::ArcPlane::XY, 0, 0, 361), std::invalid_argument);
  EXPECT_THROW(G::arc_center_angle({1, 0, 0, 0}, 2, sm::ArcPlane::YZ, 0, 0, 90), std::invalid_argument);  // 2-D
  EXPECT_THROW(G::line({0, 0, 0, 0}, {NAN, 0, 0, 0}, 2), std::invalid_argument);
}

TEST(PathFeed, TrapezoidTriangleAndEvenTime) {
  // The hexagon side (GUC L802-843): 200000 at 100 pulse/ms, 0.1 pulse/ms^2: 1000 + 1000 + 1000 ms.
  EXPECT_NEAR(sm::feed_time(200000, 100, 0.1), 3000, 1e-9);
  // GT TV37 (L1767-1787): 14.142 mm at SynAcc 1e-7 mm/ST^2: a triangle of 2*sqrt(L/A) = 23 784 ST.
  EXPECT_NEAR(sm::feed_time(std::sqrt(200.0), 0.01, 1e-7), 23784, 1);
  // evenTime (GUC L775): the cruise lasts at least evenTime, the speed is lowered to the closed form.
  const sm::FeedProfile f(1000, 0, 0, 100, 1, 20);
  EXPECT_NEAR(f.cruise_time(), 20, 1e-9);
  EXPECT_NEAR(f.peak_speed(), 0.5 * (-20 + std::sqrt(400 + 4 * 1000)), 1e-9);
  EXPECT_NEAR(f.at(f.duration()).pos, 1000, 1e-12);
  // Entry above the cap (override lowered) decelerates first; an unreachable exit is replaced.
  const sm::FeedProfile g(2000, 50, 10, 20, 1);
  EXPECT_NEAR(g.at(30).vel, 20, 1e-12);
  EXPECT_NEAR(g.at(g.duration()).pos, 2000, 1e-9);
  EXPECT_EQ(g.exit_speed(), 10);
  const sm::FeedProfile h(10, 50, 0, 50, 1);
  EXPECT_NEAR(h.exit_speed(), std::sqrt(2500 - 20.0), 1e-12);
}

TEST(CoordSystem, GtTV34_TV35_MapsAndPriority) {
  // GT L1584-1617 (TV34): 2000 pulse/mm; LnXY(10, 10) ends at 20000 pulses on axes 1 and 2.
  const auto cs = sm::CoordSystem::gt_map({{1, 2000, 0, 0, 0, 0}, {2, 0, 2000, 0, 0, 0}});
  const auto ax = cs.to_axes({10, 10, 0, 0});
  EXPECT_EQ(ax[0], 20000);
  EXPECT_EQ(ax[1], 20000);
  // GT L1627-1641 (TV35), with the manual's radians bug corrected (tan 3 deg = 0.05241, 1/cos 3 deg = 1.001372).
  const double al = 3 * kPi / 180;
  const auto skew = sm::CoordSystem::gt_map({{1, 1, std::tan(al), 0, 0, 0}, {2, 0, 1 / std::cos(al), 0, 0, 0}});
  const auto s = skew.to_axes({0, 100, 0, 0});
  EXPECT_NEAR(s[0], 5.241, 1e-3);
  EXPECT_NEAR(s[1], 100.1372, 1e-4);
  const auto back = skew.to_crd(s);
  EXPECT_NEAR(back[0], 0, 1e-9);
  EXPECT_NEAR(back[1], 100, 1e-9);
  // Conflict (GT L1665): axes 1 and 3 both map X; the lower axis decides the coordinate position.
  const auto cf = sm::CoordSystem::gt_map({{3, 1, 0, 0, 0, 0}, {1, 1, 0, 0, 0, 0}, {2, 0, 1, 0, 0, 0}});
  EXPECT_EQ(cf.axes()[0], 1);
  const auto x = cf.to_crd({7, 8, 100});
  EXPECT_NEAR(x[0], 7, 1e-12);
  EXPECT_NEAR(x[1], 8, 1e-12);
  EXPECT_THROW(sm::CoordSystem::gt_map({{1, 1, 0, 0, 0, 0}, {1, 0, 1, 0, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(sm::CoordSystem::gt_map({{5, 1, 0, 0, 0, 0}}), std::invalid_argument);
}

TEST(CoordSystem, GucCrdPrmOrigin) {
  // GUC L747-765 (§6.1), iDEABOX Ex 4-3 L1102-1171: origin (100, 100); crd (200000, 0) is profile (200100, 100).
  sm::CrdPrm p;
  p.dimension = 2;
  p.profile = {1, 2, 0, 0, 0, 0, 0, 0};
  p.syn_vel_max = 500;
  p.syn_acc_max = 1;
  p.even_time_ms = 50;
  p.set_origin = true;
  p.origin_pos = {100, 100, 0, 0, 0, 0, 0, 0};
  const auto cs = sm::CoordSystem::crd_prm(p);
  const auto ax = cs.to_axes({200000, 0, 0, 0});
  EXPECT_EQ(ax[0], 200100);
  EXPECT_EQ(ax[1], 100);
  // setOriginFlag 0: the origin is the present profile position.
  p.set_origin = false;
  const auto cs0 = sm::CoordSystem::crd_prm(p, {5, 6, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(cs0.to_axes({0, 0, 0, 0})[1], 6);
  // Two profiles on one coordinate (GUC L785) and a coordinate without profile are refused.
  p.profile = {1, 1, 0, 0, 0, 0, 0, 0};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.profile = {1, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.profile = {1, 2, 0, 0, 0, 0, 0, 0};
  p.syn_vel_max = 32767;  // open interval (0, 32767)
  EXPECT_THROW(p.validate(), std::invalid_argument);
}
