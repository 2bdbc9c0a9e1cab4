// ApsPointTables: the ADLINK PCI-8254/8258 point tables (APS_pt_*, manual §4.10.6, seed 004 L3794-3911; decisions
// AF5-AF12, session 12: AW1-AW3) as a card module: the program-memory state of each table and its buffer
// bookkeeping over the card's ADLINK interpolation group (vendor/adlink/adlink_group.hpp).
//
// A point table is a buffered continuous interpolation of a fixed axis array (2..6 axes, the first the reference
// axis). Its movement commands (line, 2-D arcs, spirals, dwell) go into the interpolation group hosted with
// kPtBufferPoints pending points (L3796) and flagged as a point table (MTS PTB while it runs, L3656), each with the
// table's own motion parameters (APS_pt_set_vm/ve/acc/dec/s: the _all form) and transition mode
// (APS_pt_set_trans_*: the card's modes 4-7 of L3117-3143). The first point of a group holds it (MF_WAIT) until
// APS_pt_start. Instruction commands (APS_pt_ext_set_do_ch / _table_no, L3822-3829) ride on the next movement
// command and are carried out on the board outputs (vendor/adlink/aps_outputs.hpp) once their move has started:
// sync() does it, and every read of the table or the outputs through the dialect calls it first (AW2).
//
// Units: pulse, pulse/s, pulse/s^2, ms (PTDWL.DwTime), degrees (arcs). Arguments are doubles as the dialect passes
// them (NaN: not a number); every function returns the APS code and never throws.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/motion/adlink_interpolation.hpp"
#include "servobench/vendor/adlink/aps_command_table.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

constexpr int kPtBufferPoints = 50;  // points per table (L3796, L3880)
constexpr int kPtTables = 2;         // table IDs 0..1 (L3796, L3858)
constexpr int kPtMaxDim = 6;         // APS type_def.h PTLINE.Pos[6]; the card interpolates 2..6 axes (L2817)
// PTSTS.BitSts bits: b0 the table moves, b1 its buffer is full (the example tests 0x02, L3901), b2 it is empty.
constexpr int kPtbWorking = 0x1, kPtbFull = 0x2, kPtbEmpty = 0x4;

// APS_get_pt_status's PTSTS (APS type_def.h): points free / holding a move not yet finished (of 50), moves started
// since APS_pt_enable.
struct PtStatus {
  int bit_sts = 0;
  int free_space = 0;
  int usage_space = 0;
  long long running_cnt = 0;
};

// One movement command as the manual's structs carry it (PTLINE, PTA2CA, PTA2CE, PTHCA, PTHCE, PTDWL); a field
// the struct has no number for is NaN (or an empty vector).
struct PtMove {
  enum class Kind { Line, Arc2Ca, Arc2Ce, SpiralCa, SpiralCe, Dwell };
  Kind kind = Kind::Line;
  double dim = std::numeric_limits<double>::quiet_NaN();  // PTLINE.Dim: the table's dimension
  std::vector<double> index;   // arcs / spirals: the table axes used, 0..n-1 in order (AF10)
  std::vector<double> pos;     // PTLINE.Pos / PTA2CE.End / PTHCE.End, pulse
  std::vector<double> center;  // pulse
  std::vector<double> normal;  // spirals
  double angle_deg = std::numeric_limits<double>::quiet_NaN();  // PTA2CA / PTHCA, + CCW
  double delta_h = std::numeric_limits<double>::quiet_NaN();    // PTHCA rise along the normal, pulse
  double final_r = std::numeric_limits<double>::quiet_NaN();    // PTHCA final radius, pulse
  double dir = std::numeric_limits<double>::quiet_NaN();        // PTA2CE / PTHCE extra laps, I16
  double dw_time_ms = std::numeric_limits<double>::quiet_NaN(); // PTDWL.DwTime, ms, 0 < t <= 1e9
};

class ApsPointTables : public machine::CardHooks {
 public:
  enum class Speed { Vm, Ve, Acc, Dec, AccDec, Sf };  // APS_pt_set_vm / _ve / _acc / _dec / _acc_dec / _s
  enum class Transition { Buffered, InPosition, BlendDec, BlendDist, BlendPcnt };  // APS_pt_set_trans_*

  explicit ApsPointTables(machine::Card& card) : card_(card) {}

  // APS_initial: no table enabled.
  void power_on() { tables_.clear(); }

  // APS_pt_enable (L3856): table 0..1 on the first `dim` (2..6) of `axes`; its speeds start as the reference axis's
  // PRA_VM/ACC/DEC/SF (AF6), absolute, buffered. One interpolation group on the card: a second table, or axes
  // that move, FunctionNotAvailable (AF5).
  AdlinkCode enable(double board, double ptb, double dim, const std::vector<double>& axes);
  // APS_pt_disable (L3860): refused while the table moves; a waiting group is dropped, the axes back to T-curve.
  AdlinkCode disable(double board, double ptb);
  // APS_get_pt_status (L3867, L3899-3901).
  AdlinkCode status(double board, double ptb, PtStatus& out);
  // APS_pt_start (L3874; `reserved` must be 0, the example's third argument L3910).
  AdlinkCode start(double board, double ptb, double reserved);
  // APS_pt_stop (L3875): decelerates along the path at the reference axis's PRA_SD_DEC, drops the points not started.
  AdlinkCode stop(double board, double ptb);

  // Movement parameters of the next points (L3808-3820).
  AdlinkCode set_relative(double board, double ptb, bool relative);
  // Vm 0 < v <= 1e9, Ve 0..1e9 pulse/s; Acc/Dec 1e-9..1e12 pulse/s^2; Sf 0..1.
  AdlinkCode set_speed(double board, double ptb, Speed which, double value);
  // Buffered (mode 4), InPosition (not simulated: FunctionNotAvailable, AF8), BlendDec (bp >= 0, unused: AF9),
  // BlendDist (0 < bp <= 1e12 pulse, mode 6), BlendPcnt (0 < bp < 100 %, mode 7).
  AdlinkCode set_transition(double board, double ptb, Transition t, double bp = 0.0);

  // Instruction commands (L3822-3829): DO channel 0..7 on/off, VAO controller 0..1 to table 0..7, carried out when
  // the next movement command starts.
  AdlinkCode ext_set_do(double board, double ptb, double channel, double on);
  AdlinkCode ext_set_table(double board, double ptb, double ctrl, double table);

  // A movement command (L3831-3838); `out` the status after it. A full buffer: FunctionNotAvailable (L3880).
  AdlinkCode push(double board, double ptb, const PtMove& m, PtStatus& out);

  // Carries out the instruction commands of every enabled table's moves that have started (AW2).
  void sync();
  bool enabled(int ptb) const { return tables_.count(ptb) != 0; }

 private:
  struct Action {
    bool vao = false;  // false: DO channel a = b; true: VAO controller a -> table b
    int a = 0, b = 0;
  };
  struct Table {
    std::vector<std::size_t> axes;
    bool relative = false;
    double vm = 0, ve = 0, acc = 0, dec = 0, sf = 0;
    motion::BlendMode mode = motion::BlendMode::Buffered;
    double blend = 0;
    double last_ve = 0;            // the VE the previous move ends with: the next one starts at it (AF7)
    std::vector<Action> ext;       // instruction commands waiting for the next movement command
    bool started = false;          // APS_pt_start given
    long long base = 0;            // moves started in the groups hosted before the present one
    long long pushed = 0;          // moves pushed into the present group
    std::map<long long, std::vector<Action>> actions;  // move index in the present group -> its commands
    long long applied = 0;         // moves whose instruction commands were carried out
  };
  // The table of (board, ptb), or the code to return.
  AdlinkCode find(double board, double ptb, Table*& t);
  bool owns_group(const Table& t) const;     // the card's interpolation group is this table's
  long long sync(Table& t);                  // returns the moves started in the present group
  PtStatus status_of(Table& t);
  AdlinkCode index_check(const Table& t, const std::vector<double>& index, std::size_t n) const;
  AdlinkCode geometry(const Table& t, const PtMove& m, motion::AdlinkMoveSpec& spec) const;

  machine::Card& card_;
  std::map<int, Table> tables_;
};

// The APS_pt_* rows (name, arguments, doc): pt_commands() of aps_command_table.hpp (AW7).

// The card's ADLINK point tables, created and attached on first use (owned by the card).
ApsPointTables& aps_point_tables(machine::Card& card);

}  // namespace servobench::vendor::adlink
