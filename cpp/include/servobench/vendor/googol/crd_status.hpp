// Coordinate-system status words as functions of a coordinate system's state (one function per manual).
//
//  - GT GT_GetCrdSts (Table 5-6, GT L1990-2011; gt.md §4.6), 16 bits: 0 coordinated motion finished or none,
//    1 buffer input finished (EndList, StpMtn, EStpMtn), 2 interpolation period too short (never here),
//    3 last coordinated command in error, 4 current segment completed, 5 axis acceleration-limit alarm,
//    6 auto-stop on an axis abnormality enabled (default 1, GT_CrdAuStpOn/Off), 7 single-segment (immediate)
//    mode, 9 an axis abnormality auto-stopped the coordinated motion, 10 internal error (never here),
//    13 buffer empty after the buffer motion started; 8, 11, 12, 14, 15 are 0.
//  - GE GT_GetCrdSts (Table 4-5 L951-968 = Table 6-16 L2023-2038; ge.md §4.5): 0 no path motion (1 idle),
//    1 buffer closed, 2 pre-processing time insufficient (never here), 4 a segment has completed, 7 immediate
//    input mode, 9 an axis fault stopped the path, 10 pulse output abnormal (never here), 13 buffer empty;
//    the others reserved (0). For the GE dialect (another helper) to fill from its own bookkeeping.
//  - GUC-ECAT / iDEABOX GT_CrdStatus(crd, &run, &segment, fifo) (GUC L692-700, iDEABOX L4574-4599):
//    run = 1 while that FIFO interpolates (a stop ramp included), segment = segments completed since the crd
//    was set up or cleared.
#pragma once

#include <cstdint>

#include "servobench/machine/card.hpp"
#include "servobench/motion/path_generator.hpp"

namespace servobench::vendor::googol {

struct CrdStatusInputs {
  bool moving = false;              // path motion in progress (a segment, a dwell, a stop ramp)
  bool buffer_closed = true;        // buffer input finished (GT EndList / StpMtn / EStpMtn; GE buffer closed)
  bool last_command_error = false;  // GT bit 3
  bool segment_complete = true;     // the current segment has completed (no segment executing)
  bool acc_limit_alarm = false;     // GT bit 5
  bool auto_stop_on = true;         // GT bit 6 (GT_CrdAuStpOn, default)
  bool immediate_mode = true;       // single-segment / immediate input mode (reset default)
  bool fault_stopped = false;       // an axis abnormality stopped the coordinated motion
  bool buffer_empty = true;         // nothing left in the buffer
  bool buffer_started = false;      // the buffer motion has started (GT bit 13 is defined only then)
};

std::uint16_t gt_crd_status(const CrdStatusInputs& in);
std::uint16_t ge_crd_status(const CrdStatusInputs& in);

struct GucCrdStatus {
  int run = 0;
  long long segment = 0;
};
GucCrdStatus guc_crd_status(const motion::PathGenerator& fifo);
// Of a card's crd 1..2 (GT_SetCrdPrm), fifo 0..1.
GucCrdStatus guc_crd_status(machine::Card& card, int crd, int fifo);

}  // namespace servobench::vendor::googol
