// GeList: the GE SX path list as a card module (GE manual seed 001 §6, L1393-2040, §12; digest ge.md §4,
// §7.9-7.11; decisions V100-V112, GV1-GV4). It owns what the GE card keeps about its continuous path besides the
// motion itself (the crd, vendor/googol/ge_crd.hpp, which it builds):
//   the feed settings   SynVel / SynAcc (pulse/ms, pulse/ms^2), StrtVel / MaxVel / StpAcc, the overrides, the
//                       GT_MapCnt work offsets (pulse) -- a changed set-up rebuilds the crd when nothing is kept;
//   the list state      immediate / buffer input mode (crd bit 7), open / closed (bit 1), the Mv start point that
//                       fixes the dimension and acceleration (L1551-1555, L5244), StrtMtn, SetDccVel for the next
//                       segment, BufIO (<= 2) / Delay (<= 1) between motion commands, BufIOBit waiting for the next
//                       segment, the segment count and end points (GT_GetMtnNm, GT_GetSegPnt);
//   look-ahead          module A (GT_InitLookAhead / AddLookData / CalVel, motion/ge_lookahead.hpp) and module B
//                       (GT_InitLookAheadEx, the Ex commands in mm, GT_M30): the card's look-ahead window in front
//                       of the buffer;
//   the command-error bit of the last path refusal (SX Table 2-4 L324-347: 8 path command, 9 buffer state, 15
//                       buffer full, 6 MapCnt) and the EXO bits the buffer wrote (merged into the output word).
// Every command returns the manual's GeCode (Table 2-2 L272-283) and never throws: a refusal records the card's
// fault (CrdStateError, or AxisStateError for MapCnt) and leaves the state unchanged. Units: the GE's, pulse and
// ms (L991-996); the Ex commands mm, mm/s with con pulse/mm. The module has no tick hooks (the crd runs as a
// group of the card's modes); reset() (GT_Reset) returns it to the power-on values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/motion/ge_lookahead.hpp"
#include "servobench/motion/path_generator.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

// TLookAheadMsg (L5147-5169): mtnNum the CodeNum where an error occurred, num the commands not sent before it,
// error 0 none, 1 the point equals the previous one, 3 buffer full (re-send), 8 sending the command failed.
struct GeLookAheadMsg {
  long long mtn_num = 0;
  long long num = 0;
  int error = 0;
};

// What the list keeps (python's former _GePathState; units pulse, ms).
struct GeListState {
  double syn_vel = 0.0;        // pulse/ms (SetSynVel; the Mv vel in buffer mode until changed)
  double syn_acc = 0.0;        // pulse/ms^2 (SetSynAcc, immediate mode)
  double strt_vel = 0.5;       // pulse/ms (L1399)
  double max_vel = 256.0;      // pulse/ms (L1405)
  double stp_acc = 0.0;        // pulse/ms^2; 0 = stop at once (V102)
  double override = 1.0, override_g0 = 1.0;
  std::vector<double> offsets;  // GT_MapCnt, pulse, one per card axis
  double capacity = 4096;      // buffered commands (V102)
  bool dirty = true;           // rebuild the crd at the next occasion
  int dim = 0;                 // crd coordinates (0: up to 4; 3 with look-ahead module B)
  bool buffer = false;         // buffer input/execution mode (crd bit 7 = 0)
  bool open = false;           // buffer open (crd bit 1 = 0)
  bool mv = false;
  int mv_dim = 4;
  double mv_vel = 0.0, mv_acc = 0.0;
  long long mv_pushed = 0;     // the Mv line is segment 0 of the generator
  bool started = false;        // StrtMtn since StrtList
  std::optional<double> dcc_vel;  // SetDccVel for the next segment
  int io_count = 0;            // BufIO since the last motion command (<= 2)
  int delay_count = 0;         // Delay since the last motion command (<= 1)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pending_io;  // BufIOBit (mask, value) for the next segment
  long long pushed = 0;        // path segments buffered since StrtList
  std::vector<motion::CrdPoint> ends;  // end points of the generator's segments, in order
  std::vector<int> end_dims;   // their dimension
  std::optional<int> cmd_bit;  // SX command-error bit of the last path refusal
  std::uint32_t exo = 0;       // the EXO word (GT_ExOpt and the buffer's writes)
  std::uint32_t gpo_seen = 0;  // the crd's buffered-output word last merged into the EXO word
  std::unique_ptr<motion::GeLookAhead> la;  // module A
  std::optional<motion::GeLookAheadParams> ex;  // module B parameters (GT_InitLookAheadEx)
  bool ex_active = false;      // module B's window is in front of the buffer (after GT_MvXYEx)
};

enum class GePlane { XY = 0, YZ = 1, ZX = 2 };

class GeList : public machine::CardHooks {
 public:
  explicit GeList(machine::Card& card);
  const GeListState& state() const { return st_; }

  // -- geometry (pulse, absolute; buffer mode appends, immediate mode runs at once at SynVel / SynAcc) ----------
  GeCode line(const std::vector<double>& point, bool g0);                         // GT_LnXY..LnXYZAG0
  GeCode arc_center(GePlane plane, double c1, double c2, double angle_deg);        // GT_ArcXY / YZ / ZX
  GeCode arc_radius(GePlane plane, double e1, double e2, double r, double direction);  // GT_ArcXYP / YZP / ZXP
  // -- feed (L1393-1419) ------------------------------------------------------------------------------------
  GeCode set_syn_vel(double vel);
  GeCode set_syn_acc(double acc);
  GeCode set_strt_vel(double vel);
  GeCode set_max_vel(double vel);
  GeCode set_stp_acc(double acc);
  GeCode set_override(double ratio, bool g0);
  GeCode set_dcc_vel(double vel);
  GeCode map_cnt(double axis, double count);  // axis 1..min(4, axes)
  // -- buffer (L1496-1664) ----------------------------------------------------------------------------------
  GeCode strt_list();
  GeCode mv(const std::vector<double>& point, double vel, double acc);
  GeCode end_list();
  GeCode add_list();
  GeCode strt_mtn();
  GeCode stp_mtn(bool abrupt);
  GeCode restore_mtn();
  GeCode buf_io(double word);
  GeCode buf_io_bit(double bit, double level);
  GeCode delay(double ms);
  // -- feedback (Table 6-15) --------------------------------------------------------------------------------
  std::uint16_t crd_status();
  // GT_GetPrfPnt (which 0), GT_GetSegPnt (1), GT_GetBrkPnt (2): up to [X, Y, Z], pulse; none = no breakpoint.
  std::optional<std::vector<double>> point(int which);
  long long mtn_nm();
  double prf_vel();
  // -- look-ahead module A (mm, mm/s) ------------------------------------------------------------------------
  GeCode init_look_ahead(const motion::GeLookAheadParams& p);
  int add_look_data(int code, int plane_group, double r, double x, double y, double z, double vel, double cx,
                    double cy, long long n, bool flag);
  int cal_vel(double& vel_mm_s, long long& number);
  // -- look-ahead module B (mm, mm/s; msg filled as TLookAheadMsg) -------------------------------------------
  GeCode init_look_ahead_ex(double t_s, double amax, double am, double n, double con);
  GeCode mv_ex(const std::vector<double>& point_mm, double vel_mm_s);
  GeCode line_ex(const std::vector<double>& point_mm, double f, double dcc, double number, bool g0,
                 GeLookAheadMsg& msg);
  GeCode arc_center_ex(GePlane plane, double c1, double c2, double angle, double f, double dcc, double number,
                       GeLookAheadMsg& msg);
  GeCode arc_radius_ex(GePlane plane, double e1, double e2, double r, double direction, double f, double dcc,
                       double number, GeLookAheadMsg& msg);
  GeCode buf_io_ex(double word);
  GeCode buf_io_bit_ex(double bit, double level);
  GeCode delay_ex(double ms);
  GeCode m30(GeLookAheadMsg& msg);
  // -- the rest of the card ---------------------------------------------------------------------------------
  // ZeroPos / SetAtlPos on crd axis a (0-based) with the path at rest and nothing kept: the crd is dropped and
  // rebuilt at the new positions by the next path command (Example 7-1 L2190; V112).
  void leave_crd(std::size_t a);
  // The EXO word EXO0..15 (GT_ExOpt; L4094-4118) with the bits the crd's buffer wrote (BufIO, BufIOBit) merged
  // in when it executed them.
  std::uint32_t outputs();
  void set_outputs(std::uint32_t word) { st_.exo = word & 0xFFFFu; }
  // The SX command-error bit of the last path refusal while that refusal is the card's last fault.
  std::optional<int> command_bit() const;

  void reset() override;

 private:
  GeCode fault(int bit);
  motion::PathGenerator& fresh();
  motion::PathGenerator& generator(bool rebuild = false);
  bool moving(const motion::PathGenerator& p) const;
  bool resumable(const motion::PathGenerator& p) const;
  template <class MakeFn>
  GeCode path_cmd(int dim, MakeFn&& make, bool g0);
  template <class Fn>
  GeCode run(Fn&& fn);
  template <class Set>
  GeCode setting(double value, double hi, bool zero_ok, Set&& set);
  std::optional<GeCode> buf_gate();
  template <class MakeFn>
  GeCode ex_motion(GeLookAheadMsg& msg, double number, double f, double dcc, MakeFn&& make, bool g0);
  motion::PathGenerator* ex_gate(GeLookAheadMsg& msg, long long number, GeCode& code);
  template <class Push>
  GeCode ex_plain(Push&& push);

  machine::Card& card_;
  GeListState st_;
};

// The card's GE list, created and attached on first use (owned by the card).
GeList& ge_list(machine::Card& card);
const GeList* ge_list_if_any(const machine::Card& card);

}  // namespace servobench::vendor::googol
