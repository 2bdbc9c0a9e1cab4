// Card: the virtual motion-control card's neutral kernel. 4 or 8 axes, one integer tick clock, staged
// (double-buffered) and active parameters, latched events, safety checked every tick. Vendor-neutral: what one
// vendor adds (registers, state machines, status words, return codes) lives in cpp/include/servobench/vendor/
// and plugs in as a module through CardHooks (machine/card_hooks.hpp; docs/architecture.md).
//
// Each axis is a MotionLoop (a profile generator coupled to an Axis: homing, capture, breakpoints) around an
// Axis the card owns or is given. Units are the controller's: pulse, pulse/tick, pulse/tick^2, pulse/tick^3
// (the GT's "per sample time"); vendor units (pulse/ms, pulse/s) are the dialects' business.
//
// One tick of the card (docs/card.md, decisions V1-V8):
//   1. commit: the axes whose Update / MltiUpdt (or a breakpoint's auto-update) is pending copy every staged
//      register into the active ones, all in this same tick (GT L1156); at a motion-cycle boundary only;
//   2. safety on the inputs at this tick instant (the mechanism where the encoder reads it now): e-stop, drive
//      alarm, hard limits (switch level x polarity, when enabled), soft limits, direction inhibit -> abrupt
//      stop / servo off before the profile advances;
//   3. the MotionLoop tick: profile advance, Axis tick (encoder read, law, filters, DAC, drive, plant over Ts),
//      capture and breakpoint on the actual position; a breakpoint with auto-update on commits this axis's
//      staged registers (effective from the next tick, GT L1263);
//   4. following error |E_n| (the law's own error this tick) against the active limit; motion-complete events
//      from the profile; then every module's after_axis(i, r) (e.g. the ADLINK error level -> servo off).
// So a fault seen in step 4 acts on the profile from the next tick (one tick, as on a DSP).
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "servobench/machine/axis.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/machine/motion_loop.hpp"
#include "servobench/motion/generator.hpp"

namespace servobench::machine {

class CardScope;  // machine/card_scope.hpp

// The card's clocks, in servo ticks.
struct CardCycles {
  double motion_cycle_ticks = 1;  // profile/commit cycle, 1..1000 (GT: 1, the profile is per ST; ADLINK: 4)
  double host_cycle_ticks = 1;    // host cycle, a whole multiple of the motion cycle, 1..10000 (ADLINK: 8)
  void validate() const;
};

// Profile mode of an axis. The values are the GT mode-register code (bits 11-13, GT L1500-1511); PVT and
// FollowEx (GUC-ECAT / iDEABOX modes the GT does not have) take the free codes 6 and 7 (decision V52).
// The kernel's own numbering: no vendor's register code. A vendor maps it to its words (GT mode register bits
// 11-13: vendor::googol::gt_mode_code).
enum class AxisMode : int { TCurve, Jog, SCurve, Gear, Coordinated, Pvt, Follow };
const char* to_string(AxisMode mode);

// Latched events of an axis (bits of CardAxisState::events), in the kernel's own order; each vendor's status word
// maps them to its bits (vendor::googol::gt_axis_status, ge_axis_status, vendor::adlink::aps_motion_status).
enum class CardEvent : int {
  MotionComplete = 0,
  DriveAlarm = 1,
  Breakpoint = 2,
  Captured = 3,
  FollowingError = 4,
  PosLimit = 5,
  NegLimit = 6,
  CommandError = 7,
  SoftPosLimit = 8,
  SoftNegLimit = 9,
  EmergencyStop = 10,
  ErrorLevel = 11,  // |E| above the servo-off error level (ADLINK PRA_ERR_POS_LEVEL)
};
constexpr std::uint32_t event_bit(CardEvent e) { return 1u << static_cast<int>(e); }
constexpr std::uint32_t kAllEvents = 0xFFFu;

// Why a command was refused. One cause per refusal; the GT command-status register maps them to bits.
enum class CommandFault : int {
  None = 0,
  MotionParamOverflow,     // a motion parameter out of range (GT cmd bit 0)
  IllegalControlParam,     // an illegal control parameter (GT cmd bit 1)
  NoAxisInMask,            // MltiUpdt(0) (GT cmd bit 2)
  DriveResetWhileEnabled,  // DrvRst with the servo on (GT cmd bit 3)
  ModeChangeInMotion,      // a mode change while moving (GT cmd bit 6)
  IndexCaptureArmed,       // CaptIndex while armed or captured (GT cmd bit 7)
  HomeCaptureArmed,        // CaptHome while armed or captured (GT cmd bit 8)
  AxisOnWhileAlarm,        // AxisOn with the drive-alarm event latched (GT cmd bit 9)
  ChangeInMotion,          // ZeroPos / SetAtlPos / SynchPos / an Update not allowed now (GT cmd bit 11)
  DirectionInhibited,      // motion toward a latched limit (no GT cmd bit; axis bit 7)
  EmergencyStopActive,     // motion while the e-stop input is active (ADLINK: ignored, stop code 1)
  InvalidInMode,           // a command the current mode does not have (e.g. SmthStp in gear mode)
  DriveAlarmActive,        // motion while the alarm input is active (ADLINK L3950-3953: ignored, stop code 2)
  DistanceTooShort,        // a point-to-point move shorter than its VS -> VE ramps (ADLINK, decision M9)
  // GE (seed 001, Tables 2-3/2-4) causes without a GT equivalent:
  MotorStateWhileEnabled,  // AlarmOn/Off, EncOn/Off with the servo enabled (GE SX cmd bit 3)
  AxisStateError,          // a servo command on a pulse axis, CtrlMode with the servo on, StepDir/Pulse on an
                           // analog axis (GE SX cmd bit 6)
  NotInCommandSet,         // a command the card variant does not have (GE SX cmd bit 14)
  NotSimulated,            // a command the simulator does not model (no vendor bit; documented per dialect)
  CrdStateError,           // [modes] a coordinated-motion command in the wrong state (GT cmd bit 12, L1800)
  NoInterruptPending,      // an interrupt command (GT_AxisI, GT_RstIntr) with no interrupt pending (GT cmd bit 4)
};
const char* to_string(CommandFault fault);

// Why an axis stopped abnormally last (ADLINK stop codes map from it).
enum class StopCause : int {
  None = 0, EmergencyStop, DriveAlarm, PosLimit, NegLimit, SoftPosLimit, SoftNegLimit, ErrorLevel, FollowingError
};
const char* to_string(StopCause cause);

class CardModes;  // machine/card_modes.hpp

// A refused card command. fault() says why; the card has recorded it (command error event and register).
class CardCommandRefused : public motion::MotionCommandRefused {
 public:
  CardCommandRefused(CommandFault fault, int axis, const std::string& what)
      : motion::MotionCommandRefused(what), fault_(fault), axis_(axis) {}
  CommandFault fault() const { return fault_; }
  int axis() const { return axis_; }  // 0-based; -1 for a card-wide command

 private:
  CommandFault fault_;
  int axis_;
};

// The double-buffered registers of one axis (GT Table 4-10, L1158-1180). Reads of the staged set are what
// GT_GetPos / GetVel / GetKp ... return (GT L4024-4036: the set value, not the profile's).
struct AxisRegisters {
  double pos = 0.0;   // target, whole pulses, -2^30..2^30-1
  double vel = 0.0;   // pulse/tick (signed in jog mode)
  double acc = 0.0;   // pulse/tick^2 (T-curve, jog)
  double macc = 0.0;  // pulse/tick^2 (S-curve)
  double jerk = 0.0;  // pulse/tick^3 (S-curve)
  double ratio = 0.0;     // electronic gear ratio (gear mode, not simulated yet)
  double brk_cn = 0.0;    // breakpoint compare value, whole pulses
  double pos_err = 32767; // following-error limit, pulse, 0..32767 (GT HardRst [8])
  LawParams law = control::GtServoLawParams{};
};

// Which staged registers (and staged commands) wait for an update.
enum StagedBit : std::uint32_t {
  kStagedPos = 1u << 0, kStagedVel = 1u << 1, kStagedAcc = 1u << 2, kStagedMAcc = 1u << 3,
  kStagedJerk = 1u << 4, kStagedRatio = 1u << 5, kStagedBrkCn = 1u << 6, kStagedPosErr = 1u << 7,
  kStagedLaw = 1u << 8, kStagedSmoothStop = 1u << 9, kStagedSynchPos = 1u << 10,
};
constexpr std::uint32_t kStagedMotion = kStagedPos | kStagedVel | kStagedAcc | kStagedMAcc | kStagedJerk;

// Limit configuration of an axis. Hard limits are the switches of the axis (plant/switches.hpp, load angle);
// the input level is 1 while the switch is hit (a normally-closed switch opens: GT L627-631), and an input
// "triggers" when level != active_low. Soft limits compare the actual position (card coordinates).
struct LimitConfig {
  bool enabled = true;           // GT_LmtsOn (default) / GT_LmtsOff: react to the hard limits
  bool pos_active_low = false;   // GT_LmtSns bit 2(k-1): 0 triggers on high (default), 1 on low
  bool neg_active_low = false;   // GT_LmtSns bit 2(k-1)+1
  bool soft_pos_enabled = false; // ADLINK PRA_SPEL_EN
  bool soft_neg_enabled = false; // ADLINK PRA_SMEL_EN
  double soft_pos_pulse = 0.0;   // ADLINK PRA_SPEL_POS: triggers at actual >= this
  double soft_neg_pulse = 0.0;   // ADLINK PRA_SMEL_POS: triggers at actual <= this
  void validate() const;
};

// The card's per-axis state that is not inside the MotionLoop.
struct CardAxisState {
  AxisMode mode = AxisMode::TCurve;  // reset default T-curve (GT HardRst [5])
  AxisRegisters staged{}, active{};
  std::uint32_t dirty = 0;          // StagedBit written since the last Update
  // Update / MltiUpdt take the staged registers as they are at the call; they become active at the next
  // (motion-cycle) tick. Later writes are staged for the next update (or a breakpoint's auto-update).
  AxisRegisters pending{};
  std::uint32_t pending_dirty = 0;
  bool commit_pending = false;
  // A breakpoint armed while an update with a new BrkCn waits: armed right after that commit (V26).
  bool brk_deferred = false;
  motion::BreakKind brk_deferred_kind = motion::BreakKind::None;
  std::uint32_t events = 0;         // latched CardEvent bits
  bool enabled = false;             // drive enabled (GT_AxisOn / AxisOff; status bit 9); off at power-on (V11)
  bool closed_loop = true;          // GT_CloseLp (default) / GT_OpenLp
  double mtr_cmd = 0.0;             // open-loop output, DAC counts -32767..32767 (GT_SetMtrCmd)
  bool auto_stop = false;           // GT_AuStpOn: following error stops and disables the axis
  bool auto_update = false;         // GT_AuUpdtOn: a breakpoint commits the staged registers
  bool alarm_enabled = true;        // react to the drive-alarm input (GE GT_AlarmOn/Off; on by default)
  bool alarm_input = false;         // the ALM input forced by the user (besides the drive's own alarm)
  bool alarm_prev = false;          // the alarm input level at the previous tick
  LimitConfig limits{};
  double error_pulse = 0.0;         // the law's error E_n of the last tick (planned - actual), pulse
  bool following_error_now = false; // the check failed in the last tick (enabled, closed loop, |E| > limit)
  StopCause stop_cause = StopCause::None;  // cleared when the next motion starts (ADLINK ASTP, L3652)
  bool was_moving = false;
  bool dir_positive = false;        // the direction of the last profile motion, kept after the stop (decision VK3)
  bool encoder_fault = false;       // the encoder-abnormal input, set by the user: counts as a following error
};

// What one tick of one axis records (each a buffer of n doubles or null), besides the Axis and loop traces.
struct CardTrace {
  Trace axis{};
  LoopTrace loop{};
  double* events = nullptr;    // latched CardEvent bits after the tick
  double* moving = nullptr;    // 1 while the profile moves (GT status bit 10)
  double* servo_on = nullptr;  // 1 while the drive is enabled (GT status bit 9)
  double* prf_vel = nullptr;   // profile velocity, pulse/tick
};

class Card {
 public:
  // A card that owns `axes` (4 or 8) axes built from `axis_config`.
  Card(int axes, const AxisConfig& axis_config, const CardCycles& cycles = {});
  // A card around the given axes (kept by pointer; they must outlive the card): 4 or 8 of them, one servo period.
  explicit Card(const std::vector<Axis*>& axes, const CardCycles& cycles = {});
  Card(const Card&) = delete;
  Card& operator=(const Card&) = delete;
  ~Card();

  // -- structure and clocks ------------------------------------------------------------------------------
  std::size_t axis_count() const { return loops_.size(); }
  Axis& axis(std::size_t i) { return loop(i).axis(); }
  MotionLoop& loop(std::size_t i);
  const MotionLoop& loop(std::size_t i) const;
  const CardAxisState& state(std::size_t i) const;
  long long tick() const { return tick_; }
  double servo_period_s() const { return period_s_; }
  const CardCycles& cycles() const { return cycles_; }

  // Reset (GT_Reset / GT_HardRst, L4124-4142; GE L4769-4786): registers, events, capture and breakpoints
  // cleared, T-curve, gains 0, ILmt/MtrLmt/PosErr 32767, auto-update and auto-stop off, closed loop, limits
  // on with polarity 0, soft limits off, drives disabled, e-stop released; the clock and mechanics keep going.
  void reset();

  // -- staged (double-buffered) registers: GT_SetPos/Vel/Acc/MAcc/Jerk/Ratio/BrkCn/PosErr/Kp.../SmthStp/SynchPos
  void stage_pos(std::size_t i, double pos);
  void stage_vel(std::size_t i, double vel);
  void stage_acc(std::size_t i, double acc);
  void stage_macc(std::size_t i, double macc);
  void stage_jerk(std::size_t i, double jerk);
  void stage_ratio(std::size_t i, double ratio);
  void stage_brk_cn(std::size_t i, double brk_cn);
  void stage_pos_err(std::size_t i, double pos_err);
  void stage_law(std::size_t i, const LawParams& law);  // validated; must be the axis's law family
  void stage_smooth_stop(std::size_t i);
  void stage_synch_pos(std::size_t i);
  // GT_Update (one axis) / GT_MltiUpdt (bit k = axis k+1): every staged change of the masked axes is
  // committed together at the next tick. Checked now against the axis state; a refused update commits nothing.
  void update(std::uint32_t mask);

  // -- immediate commands ---------------------------------------------------------------------------------
  void set_mode(std::size_t i, AxisMode mode);  // GT_PrflT/S/V; refused while moving (GT L837)
  void abrupt_stop(std::size_t i);              // GT_AbptStp: velocity 0 at once, motion complete
  void zero_pos(std::size_t i) { set_actual_pos(i, 0.0); }  // GT_ZeroPos
  // GT_SetAtlPos: actual (encoder) = target = profile = pos, at rest (GT L4613-4622, GE L5457-5463); the
  // mechanism does not move, a following error left at rest is dropped.
  void set_actual_pos(std::size_t i, double pos);
  // GTS GT_ZeroPos(axis, count): zeroes `count` axes from `first`, all or none (every axis is checked first).
  void zero_pos_range(std::size_t first, std::size_t count);
  // Refuses (CardCommandRefused) unless ZeroPos/SetAtlPos may act on axis i now: not in gear mode, not in a
  // coordinate system, at rest (GT L1421-1429, L4617, L5200; GE L5461, L5909).
  void check_position_set(std::size_t i);
  void axis_on(std::size_t i);                   // GT_AxisOn: refused with the alarm latched; motion complete
  void axis_off(std::size_t i);                  // GT_AxisOff
  void drive_reset(std::size_t i);               // GT_DrvRst: only with the drive disabled
  void set_closed_loop(std::size_t i, bool closed);  // GT_CloseLp / GT_OpenLp
  void set_mtr_cmd(std::size_t i, double counts);    // GT_SetMtrCmd: open-loop output, -32767..32767
  void set_auto_stop(std::size_t i, bool on) { at(i).auto_stop = on; }
  void set_auto_update(std::size_t i, bool on) { at(i).auto_update = on; }
  void arm_breakpoint(std::size_t i, motion::BreakKind kind);  // GT_PosBrk/NegBrk/MtnBrk/ExtBrk, None = BrkOff
  void arm_capture(std::size_t i, CaptureTrigger trigger);    // GT_CaptHome/CaptIndex (None disarms)
  void home(std::size_t i, const motion::GtHomeParams& p);    // GT_Home / GT_Index automatic homing

  // -- safety configuration and inputs ----------------------------------------------------------------------
  void set_limits(std::size_t i, const LimitConfig& limits);
  void set_alarm_enabled(std::size_t i, bool on) { at(i).alarm_enabled = on; }
  void set_alarm_input(std::size_t i, bool alarm) { at(i).alarm_input = alarm; }
  void set_emergency_stop(bool active) { estop_ = active; }
  bool emergency_stop() const { return estop_; }

  // -- events ---------------------------------------------------------------------------------------------
  // Clears the latched events in `which` (CardEvent bits). The following-error event stays while the check
  // still fails (GT L1453: "only when the axis is not in motion error status"). Clearing a limit event ends
  // the direction inhibit (a limit still triggered latches it again at the next tick).
  void clear_events(std::size_t i, std::uint32_t which);
  std::uint32_t events(std::size_t i) const { return state(i).events; }
  // Records a refusal decided outside (a dialect's own range check): command-error event and fault register.
  void record_fault(int axis, CommandFault fault);
  // The last refusal's cause (GT_GetCmdSts).
  CommandFault last_fault() const { return last_fault_; }

  // -- readbacks ------------------------------------------------------------------------------------------
  bool moving(std::size_t i) const;        // the profile runs (GT status bit 10; always in gear mode)
  bool servo_on(std::size_t i) const { return state(i).enabled; }  // drive enabled (GT status bit 9)
  bool closed_loop(std::size_t i) const { return state(i).closed_loop; }
  long long profile_pos(std::size_t i) const { return loops_[i]->generator().reported_pos(); }
  double profile_vel(std::size_t i) const { return loops_[i]->generator().state().vel; }
  double actual_pos(std::size_t i) const { return loops_[i]->actual_pos(); }
  double following_error(std::size_t i) const { return state(i).error_pulse; }  // GT_GetAtlErr
  bool pos_limit_input(std::size_t i) const;  // hard-limit inputs as triggered (polarity applied)
  bool neg_limit_input(std::size_t i) const;

  // -- neutral commands first met in the GE manual (decisions V86-V99, VK4) ------------------------------------
  // GE GT_SmthStp: an immediate smooth stop at the mode's limits (GE L1310-1312, Example 7-2 L2245); no-op at rest.
  void smooth_stop(std::size_t i);
  // GE GT_CaptProb: every axis's capture armed on the probe input EXI0, one shot (GE L3828-3862); refused as a
  // whole (HomeCaptureArmed) if an axis is armed or still flags a capture.
  void arm_probe();
  // (the probe edge itself: set_probe_time below, the scope block)
  void set_encoder_fault(std::size_t i, bool on) { at(i).encoder_fault = on; }
  // GE GT_AxisOn's synchronisation (L3716-3720): target = profile = the actual position (whole pulses), at once;
  // at rest only (else ChangeInMotion).
  void synch_pos_now(std::size_t i);
  // -- [modes] gear, PVT, FollowEx and coordinate systems: machine/card_modes.hpp (created on first use) -----
  CardModes& modes();
  const CardModes* modes_if_any() const { return modes_.get(); }

  // -- modules (machine/card_hooks.hpp): what the neutral kernel does not know plugs in here ----------------------
  // Attaches a module (kept by reference; it must outlive the card or be detached). Its hooks run after those
  // attached before it.
  void attach(CardHooks& module);
  void detach(CardHooks& module);
  // The card's module of type M (a vendor module: vendor/adlink/adlink_axes.hpp ...), created from the card and
  // attached on first use, owned by the card. The kernel knows it only as CardHooks.
  template <class M>
  M& module() {
    if (M* m = find_module<M>()) return *m;
    auto owned = std::make_unique<M>(*this);
    M& m = *owned;
    attach(m);
    owned_modules_.push_back(std::move(owned));
    return m;
  }
  // The card's module of type M if created, else null.
  template <class M>
  const M* module_if_any() const {
    for (const auto& o : owned_modules_)
      if (const M* m = dynamic_cast<const M*>(o.get())) return m;
    return nullptr;
  }

  // -- kernel services: what a module may use (docs/architecture.md "The hook interface") ---------------------------
  // The one axis-index check: ValueError (std::invalid_argument) naming the axis unless i < axis_count().
  void check_axis(std::size_t i) const;
  // Records the refusal (command-error event and register, last_fault) and throws CardCommandRefused.
  [[noreturn]] void refuse(int axis, CommandFault fault, const std::string& what);
  // A module's driven mode (gear, PVT, cam, coordinated) takes axis i, or gives it back (AxisMode::TCurve).
  void set_driven_mode(std::size_t i, AxisMode mode);
  // The stop cause of axis i (ADLINK stop code): a refused group start records it, a group start clears it.
  void set_stop_cause(std::size_t i, StopCause cause);
  // Abrupt stop of axis i's own profile, motion-complete event (no hooks called).
  void stop_profile(std::size_t i);
  bool alarm_active(std::size_t i) const;  // the drive-alarm input of axis i, as the card reacts to it
  // Before an immediate move of direction dir (sign; 0: none) on axis i: refuses (recording the ignored command's
  // stop cause) in a driven mode, during a sequence, while the e-stop, the alarm input or a latched limit toward
  // dir is active (ADLINK L3931-4010).
  void check_move_allowed(std::size_t i, double dir);
  // Stops axis i for `cause`: the modules' on_fault, the profile stopped (motion complete), the stop cause
  // recorded; with servo_off the drive is disabled.
  void fault_stop(std::size_t i, StopCause cause, bool servo_off);
  // Latches event e on axis i.
  void latch_event(std::size_t i, CardEvent e);
  // The target registers (staged and active) take pos, whole pulses: an immediate move's target reads back.
  void set_target_pos(std::size_t i, double pos);
  bool inhibited_pos(std::size_t i) const;  // motion toward + is inhibited (a latched hard or soft limit)
  bool inhibited_neg(std::size_t i) const;

  // -- running ----------------------------------------------------------------------------------------------
  // Runs n ticks. traces: empty, or one per axis whose non-null buffers hold n doubles each.
  void run(std::size_t n, const std::vector<CardTrace>& traces = {});

  // -- scope, events, compare, probe (issue 10 point 3; machine/card_scope.hpp, docs/card.md "Scope") ------------
  // The sampler, the position compare, the event watch and the probe-at-a-position, created on first use; a card
  // that never asks for it runs as before.
  CardScope& scope();
  bool has_scope() const { return scope_ != nullptr; }
  // Runs at most n ticks and stops after the tick in which a watched event fired (scope().fired() lists them);
  // returns the ticks run. traces: as for run(), buffers of n doubles.
  std::size_t run_until_event(std::size_t n, const std::vector<CardTrace>& traces = {});
  // The probe input EXI0 at time t_s on the card clock (s, tick k spans [k Ts, (k+1) Ts); NaN: never): every
  // axis armed for the probe latches its actual position at that instant (GT_CaptProb, GT L3008-3049).
  void set_probe_time(double t_s);

 private:
  void init(const CardCycles& cycles);
  CardAxisState& at(std::size_t i);
  void touch(std::size_t i, std::uint32_t bits);
  // Runs a validation; its std::invalid_argument also records `fault` (command-error event) before it propagates.
  template <class F>
  void checked(std::size_t i, CommandFault fault, F&& check) {
    try {
      check();
    } catch (const std::invalid_argument&) {
      record_fault(static_cast<int>(i), fault);
      throw;
    }
  }
  void apply_output(std::size_t i);
  // What committing registers r with changes d on axis i would refuse now (None = fine); `why` gets the message.
  CommandFault check_commit(std::size_t i, const AxisRegisters& r, std::uint32_t d, std::string* why) const;
  void commit(std::size_t i, const AxisRegisters& r, std::uint32_t d);
  void tick_once(const std::vector<CardTrace>& traces, std::size_t k);
  void safety_before(std::size_t i);
  void after_tick(std::size_t i, const LoopTick& r);
  void record(std::size_t i, const CardTrace& ct, std::size_t k) const;
  void limit_stop(std::size_t i, StopCause cause);
  template <class M>
  M* find_module() {
    for (const auto& o : owned_modules_)
      if (M* m = dynamic_cast<M*>(o.get())) return m;
    return nullptr;
  }
  std::vector<std::unique_ptr<CardHooks>> owned_modules_;  // module<M>()'s, attached in creation order
  // [modes] owned, and attached as a module like any other
  std::unique_ptr<CardModes> modes_;
  std::vector<CardHooks*> hooks_;  // attached modules, in attach order
  bool limit_enabled(std::size_t i, bool positive) const;

  std::vector<std::unique_ptr<Axis>> owned_;
  std::vector<std::unique_ptr<MotionLoop>> loops_;
  std::vector<CardAxisState> st_;
  CardCycles cycles_{};
  double period_s_ = 0.0;
  long long tick_ = 0;
  bool estop_ = false;
  CommandFault last_fault_ = CommandFault::None;
  // scope, events, compare, probe (issue 10 point 3)
  std::unique_ptr<CardScope> scope_;
  void scope_tick();
};

}  // namespace servobench::machine
