// The GUC-ECAT / iDEABOX (GTS library) commands that set up a profile, a coordinate system or a PVT table, as
// vendor functions: each checks its arguments against the manual's ranges and returns the manual's GucCode
// (0 success, 1 command error: the card refused it in its present state, nothing changed; 7 parameter error; GUC
// Tab 2-1 L165-180, iDEABOX Table 3-1 L333-361); none throws for a bad value (a NaN is out of every range).
// Arguments as the manuals print them: profiles/axes from 1, crd 1..2, fifo 0..1; units pulse, ms, pulse/ms,
// pulse/ms^2 (converted to the kernel's pulse/tick through the servo period). The registers the kernel does not
// hold are the card's GtsCard (gts_card.hpp); servobench.dialects.gts is one row per command over these.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/motion/coord_system.hpp"
#include "servobench/motion/pvt.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

// GT_SetTrapPrm (GUC L2898-2908; TTrapPrm GUC L213-223): acc and dec > 0 pulse/ms^2 (the card's T-curve has one
// acceleration for both ramps: dec is checked and taken equal to acc, decision V61); velStart and smoothTime must
// be 0 (not simulated: 7 otherwise).
GucCode gts_set_trap_prm(machine::Card& card, double profile, double acc, double dec, double vel_start,
                         double smooth_time);
// GT_SetJogPrm (iDEABOX Ex 4-1 L726-730, TJogPrmExt): acc/dec as GT_SetTrapPrm, smooth 0..1 (recorded, GS17).
GucCode gts_set_jog_prm(machine::Card& card, double profile, double acc, double dec, double smooth);
// GT_Stop(mask, option) (GUC L232-239; iDEABOX L1793): bit k = axis k+1, bit 12 = crd 1, bit 13 = crd 2; the same
// bit of option set = abrupt, clear = smooth. A point-to-point / jog axis stops at its GT_SetStopDec deceleration
// (GS7); an axis in another mode outside a crd stops at once; a stopped crd keeps its breakpoint.
GucCode gts_stop(machine::Card& card, double mask, double option);

// TCrdPrm as the manual passes it (GUC L371-388, iDEABOX L7113-7164): every field as given, checked by
// gts_set_crd_prm.
struct GtsCrdPrm {
  double dimension = 2;                 // 1..4
  std::vector<double> profile;          // <= 8 entries, profile[k] = coordinate (1 X .. 4 A, 0 none) of profile k+1
  double syn_vel_max = 0;               // (0, 32767) pulse/ms
  double syn_acc_max = 0;               // (0, 32767) pulse/ms^2
  double even_time = 0;                 // whole, [0, 32767) ms
  double set_origin_flag = 0;           // 0 origin = present profile positions, 1 = origin_pos
  std::vector<double> origin_pos;       // <= 8 entries, whole pulse, int32
};
// GT_SetCrdPrm (GUC L369-388, L736-792; iDEABOX L7095-7176): 7 for a value out of range, a profile mapped twice
// or beyond the dimension, a dimension the profiles do not fill (L785) or a profile the card does not have; 1
// while a mapped axis moves or is in the other crd (L743, L7168-7174). Drops the crd's look-ahead windows.
GucCode gts_set_crd_prm(machine::Card& card, double crd, const GtsCrdPrm& prm);
// GT_GetCrdPrm: (0, the crd's parameters), (1, {}) when the crd is not set up, (7, {}) for a bad crd.
std::pair<GucCode, motion::CrdPrm> gts_get_crd_prm(machine::Card& card, double crd);
// GT_InitLookAhead (GUC L725-732, L908-995; iDEABOX L5848-5879): corner time T (0, 1000] ms, accMax
// (0, 32767] pulse/ms^2, window n 0..32766 segments (0 = off); 1 when the crd is not set up.
GucCode gts_init_lookahead(machine::Card& card, double crd, double fifo, double t_ms, double acc_max, double n);
// GT_CrdData(crd, NULL, fifo) (GUC L975-977; iDEABOX L4465-4498): moves the look-ahead window into the FIFO; 1
// when the FIFO filled first (call again after GT_CrdSpace). Raw TCrdData records (null_data false): 7 (not
// simulated).
GucCode gts_crd_data(machine::Card& card, double crd, bool null_data, double fifo);

// -- PVT tables (GUC §4.2 L1116-2100, iDEABOX §4.4): the first `count` values of each array (whole, at most the
// shortest array's length: 7 otherwise), table id 1..32 (GUC L1304); 7 when the data makes no table (the
// builders' rules, pvt.hpp), 1 when the card refuses the download (a table an axis is running).
GucCode gts_pvt_table(machine::Card& card, double table_id, double count, const std::vector<double>& time_ms,
                      const std::vector<double>& pos, const std::vector<double>& vel);                // GUC L1169
GucCode gts_pvt_table_ex(machine::Card& card, double table_id, double count, const std::vector<double>& time_ms,
                         const std::vector<double>& pos, const std::vector<double>& vel_begin,
                         const std::vector<double>& vel_end);                                         // iDEABOX L6446
GucCode gts_pvt_table_complete(machine::Card& card, double table_id, double count,
                               const std::vector<double>& time_ms, const std::vector<double>& pos, double vel_begin,
                               double vel_end);                                                       // GUC L1181-1191
GucCode gts_pvt_table_percent(machine::Card& card, double table_id, double count, const std::vector<double>& time_ms,
                              const std::vector<double>& pos, const std::vector<double>& percent,
                              double vel_begin);                                                      // GUC L1436-1457
// Continuous (GUC L1475-1504) and Continuous-Ex (iDEABOX L6745-6803, ex: separate acc/dec S shares): the
// first count points of pts; the first point's time is time_begin_ms.
GucCode gts_pvt_table_continuous(machine::Card& card, double table_id, double count,
                                 const motion::ContinuousPoints& pts, double time_begin_ms, bool ex);
// GT_PvtPercentCalculate (GUC L1436; iDEABOX L6259): (0, node velocities pulse/ms) or (7, {}); no card needed.
std::pair<GucCode, std::vector<double>> gts_pvt_percent_calculate(double count, const std::vector<double>& time_ms,
                                                                  const std::vector<double>& pos,
                                                                  const std::vector<double>& percent,
                                                                  double vel_begin);
// GT_PvtContinuousCalculate (GUC L1230; iDEABOX L6222-6251): (0, point times ms, time[0] = 0) or (7, {}).
std::pair<GucCode, std::vector<double>> gts_pvt_continuous_calculate(double count,
                                                                     const motion::ContinuousPoints& pts);

// -- the command table and the runner (decisions GX1-GX3) ---------------------------------------------------------
// gts_command_table(): every GTS function servobench.dialects.gts makes from a row, described once: the manual's
// name, its parameters as the Python names and defaults, what a read returns after the code when it fails (a
// Python literal, "" for a command), and the docstring (what it does, units, the manual's lines).
struct GtsCommandRow {
  const char* name;    // GT_* as the manual spells it
  const char* params;  // "profile, count=1", "crd, prm: TCrdPrm"
  const char* fail;    // a read's placeholders after a failing code, e.g. "(0, 0.0)"; "" for a command
  const char* doc;
};
const std::vector<GtsCommandRow>& gts_command_table();

// A command's reply: the code and, for a read that succeeded, its values, each an integer ('i'), a double ('f'), or
// all of them one list of doubles ("l": GT_GetCrdPos).
struct GtsReply {
  GucCode code = GucCode::Success;
  std::vector<double> values;
  std::string kinds;
};
// The names gts_command runs: the per-axis, coordinate-system (buffered and path), PVT and FollowEx commands whose
// arguments are numbers.
std::vector<std::string> gts_command_names();
// Runs GTS command `name` with its arguments as doubles in the manual's units (axes/profiles from 1, crd 1..2, fifo
// 0..1; pulse, ms, pulse/ms, pulse/ms^2). The argument checks are here, once, in the order the dialect had them:
// the axis/crd/fifo numbers and the values' ranges (7), then the card's own refusal (1) or an invalid value (7).
// Never throws for a name in gts_command_names() given its row's parameters; an unknown name throws
// std::invalid_argument (a programming error of the dialect).
GtsReply gts_command(machine::Card& card, const std::string& name, const std::vector<double>& args);
// GT_FollowDataCompleteEx(profile, fifo, n, master, slave, velRatioBegin, velRatioEnd) (iDEABOX L4644-4677): n
// knots 2..2^31-1 (cumulative positions, pulse), at most each array's length (7 otherwise).
GucCode gts_follow_data_complete(machine::Card& card, double profile, double fifo, double n,
                                 const std::vector<double>& master, const std::vector<double>& slave,
                                 double ratio_begin, double ratio_end);

}  // namespace servobench::vendor::googol
