// CardHooks: how a module plugs into the card kernel (machine/card.hpp; docs/architecture.md "The hook interface").
//
// A module is what the neutral kernel does not know: a driven-axis mode (gear, PVT, cam, coordinate systems:
// machine/card_modes.hpp) or, as they move out of the kernel, a vendor's registers and state machines
// (cpp/include/servobench/vendor/). The card calls the hooks of every attached module at fixed points of its tick
// and of its commands, in the order the modules were attached; each hook's default does nothing, so a module
// overrides what it needs. A module reaches the kernel only through the card's public methods (its "kernel
// services": check_axis, refuse, record_fault, set_driven_mode, set_stop_cause, stop_profile, alarm_active,
// inhibited_pos/neg, check_move_allowed, fault_stop, latch_event, set_target_pos, loop, state, ...): no friend
// classes. A vendor module the card owns is created with Card::module<M>() (vendor/adlink/adlink_axes.hpp).
//
// The tick, with the hooks (card.hpp "One tick"):
//   1. commit pending updates                                   on_ratio(i, r) when a gear ratio commits
//   2. safety on this instant's inputs                          limit_enabled(i, positive), on_fault(i, cause)
//   3. begin_tick(tick) once, then per axis i in ascending order: feed(i), MotionLoop::step, the kernel's checks
//      after it, then after_axis(i, r) with what the step returned (a vendor's error level, distance events)
//   (in 2., a latched limit in the direction of motion: on_limit(i, cause) may stop the axis its own way)
// Commands: set_mode -> leave(i); abrupt_stop -> on_abrupt_stop(i); reset -> reset(); a move's direction check
// -> inhibits_move(i, dir); the status bit "moving" -> moving(i).
// Events: a module watches the card's words with its own masks (CardScope::set_vendor_watch, apart from the host's
// Card.on_event subscriptions); on_watch(e) gets what fired, after every axis ran the tick.
#pragma once

#include <cstddef>
#include <optional>

namespace servobench::machine {

enum class StopCause : int;  // machine/card.hpp
struct FiredEvent;           // machine/card_scope.hpp: an event of a watch
struct LoopTick;             // machine/motion_loop.hpp: what one tick of an axis returned

class CardHooks {
 public:
  virtual ~CardHooks() = default;

  // False: the card skips begin_tick and feed this tick (a module with nothing to drive costs nothing).
  virtual bool active() const { return false; }
  // Once per tick, before the axes run: advance buffers, lists, interpolators.
  virtual void begin_tick(long long /*tick*/) {}
  // Before axis i's loop step: a driven axis gets its command (ProfileGenerator::follow).
  virtual void feed(std::size_t /*i*/) {}
  // Whether the card sees this hard limit of axis i (GUC BufLmtsOff hides it while its buffer place runs).
  virtual bool limit_enabled(std::size_t /*i*/, bool /*positive*/) const { return true; }
  // After the kernel's checks on axis i this tick (following error, events): r is what MotionLoop::step returned
  // (the law's error E_n, the actual position). Called for every attached module, active or not.
  virtual void after_axis(std::size_t /*i*/, const LoopTick& /*r*/) {}
  // Axis i moves toward a latched limit (cause: PosLimit ... SoftNegLimit). True: the module stops it its own way
  // (an ADLINK decelerating limit stop, PRA_EL_MODE 1); false: the kernel stops it at once.
  virtual bool on_limit(std::size_t /*i*/, StopCause /*cause*/) { return false; }
  // The kernel stopped axis i for `cause` (e-stop, alarm, limit, following error): stop what depends on it.
  virtual void on_fault(std::size_t /*i*/, StopCause /*cause*/) {}
  // GT_AbptStp on axis i.
  virtual void on_abrupt_stop(std::size_t /*i*/) {}
  // A committed gear ratio of axis i.
  virtual void on_ratio(std::size_t /*i*/, double /*ratio*/) {}
  // A move of axis i in direction dir (+1/-1) would drive something the module moves toward a latched limit.
  virtual bool inhibits_move(std::size_t /*i*/, double /*dir*/) const { return false; }
  // Axis i leaves the module's mode (a mode select).
  virtual void leave(std::size_t /*i*/) {}
  // Card reset (GT_Reset / HardRst): back to the power-on state.
  virtual void reset() {}
  // The module's notion of "moving" for axis i (GT status bit 10); nullopt: the kernel's.
  virtual std::optional<bool> moving(std::size_t /*i*/) const { return std::nullopt; }
  // An event of the module's own watch (CardScope::set_vendor_watch) fired in tick e.tick (e.bits: the module's bits
  // only), called after every axis ran that tick. The module may command the card, change its watch, and end a
  // Card::run_until_event after this tick (CardScope::request_stop).
  virtual void on_watch(const FiredEvent& /*e*/) {}
};

}  // namespace servobench::machine
