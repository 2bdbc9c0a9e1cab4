// GtCrdList: the GT coordinated-motion list (vendor/googol/gt_crd_list.hpp).
#include "servobench/vendor/googol/gt_crd_list.hpp"

#include <algorithm>
#include <cmath>

#include "servobench/machine/card_group.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/motion/coord_system.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/vendor/googol/crd_status.hpp"
#include "servobench/vendor/googol/gt_card.hpp"

namespace servobench::vendor::googol {

using machine::CommandFault;
using motion::CrdPoint;
using motion::PathSegmentGeometry;

namespace {

constexpr double kPosMin = -1073741824.0, kPosMax = 1073741823.0;  // L854
constexpr double kSynMax = 16384.0;                                  // pulse/ST, pulse/ST^2 (L401)

bool finite_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi; }

}  // namespace

GtCode GtCrdList::refuse(int bit, GtCode code) {
  r_.error = true;
  r_.cmd_bit = bit;
  gt_.card().record_fault(static_cast<int>(gt_.axis()), CommandFault::CrdStateError);
  return code;
}

motion::PathGenerator* GtCrdList::path() {
  try {
    return &gt_.card().modes().gt_path();
  } catch (const motion::MotionCommandRefused&) {
    return nullptr;
  }
}

const motion::PathGenerator* GtCrdList::path_if_set_up() const {
  const machine::CardModes* modes = gt_.card().modes_if_any();
  if (modes == nullptr || !modes->hosted(machine::kGtCrdSlot).group) return nullptr;
  return &static_cast<const machine::PathGroup*>(modes->group(machine::kGtCrdSlot))->path();
}

GtCode GtCrdList::run(const std::function<void()>& command, bool mv) {
  const GtCode code = gt_.run(command);
  r_.error = code != GtCode::Success;
  if (code != GtCode::CommandError) return code;
  const motion::PathGenerator* p = path();
  if (p != nullptr && p->fifo_space() <= 0) return refuse(15);  // buffer full: send it again (L477-478)
  if (mv) return refuse(13);
  const CommandFault f = gt_.card().last_fault();
  if (f == CommandFault::ChangeInMotion || f == CommandFault::InvalidInMode) return refuse(12);  // L1800
  return code;
}

void GtCrdList::apply_acc_lmt() {
  if (path_if_set_up() == nullptr) return;
  motion::PathGenerator& p = gt_.card().modes().gt_path();
  const motion::PathSetup& s = p.setup();
  const std::array<double, 4> now{s.axis_acc_1, s.axis_acc_2, s.axis_acc_3, s.axis_acc_4};
  for (int k = 0; k < 4; ++k)
    if (now[k] != r_.acc_lmt[k]) p.set_axis_acc(k + 1, r_.acc_lmt[k]);
}

GtCode GtCrdList::map_axis(double axis, const std::vector<double>& counts) {
  bool ok = counts.size() == 5;
  for (double c : counts) ok = ok && finite_in(c, -1e12, 1e12);
  if (!ok) return gt_.check(NAN, 0, 0);
  if (GtCode c = gt_.check(axis, 1, 4); c != GtCode::Success) return c;
  try {
    gt_.card().modes().gt_map_axis({static_cast<int>(axis), counts[0], counts[1], counts[2], counts[3], counts[4]});
    apply_acc_lmt();
  } catch (const motion::MotionCommandRefused&) {
    return refuse();
  } catch (const motion::PathGeometryError& e) {
    return gt_geometry_code(e.gt_code());  // a map that determines no coordinate: 6 (L408)
  } catch (const std::invalid_argument&) {
    return GtCode::ParameterError;
  }
  return GtCode::Success;
}

GtCode GtCrdList::set_syn_vel(double vel) {
  if (!finite_in(vel, 0, kSynMax) || vel == 0) return GtCode::SynParamError;  // Table 2-1 L401
  r_.vel = vel;
  return GtCode::Success;
}

GtCode GtCrdList::set_syn_acc(double acc) {
  if (!finite_in(acc, 0, kSynMax) || acc == 0) return GtCode::SynParamError;
  r_.acc = acc;
  return GtCode::Success;
}

GtCode GtCrdList::set_acc_lmt(double acc) {
  if (GtCode c = gt_.check(acc, 0, kSynMax, GtArg::Real, CommandFault::MotionParamOverflow); c != GtCode::Success)
    return c;
  r_.acc_lmt[gt_.axis()] = acc;
  return gt_.run([&] { apply_acc_lmt(); });
}

GtCode GtCrdList::path_command(const std::function<PathSegmentGeometry(const CrdPoint&, int)>& make) {
  motion::PathGenerator* p = path();
  if (p == nullptr) return refuse();
  if (r_.buffer && r_.open && !r_.mv) return refuse();  // Mv* must follow StrtList (L1843)
  if (!(r_.vel > 0 && r_.acc > 0)) return gt_.check(NAN, 0, 0, GtArg::Real, CommandFault::MotionParamOverflow);
  std::optional<PathSegmentGeometry> seg;
  try {
    seg = make(p->tail(), p->coords().dim());
  } catch (const motion::PathGeometryError& e) {
    r_.error = true;
    return gt_geometry_code(e.gt_code());
  } catch (const std::invalid_argument&) {
    r_.error = true;
    return GtCode::ParameterError;
  }
  const double vel = r_.vel, acc = r_.acc;
  if (r_.buffer && r_.open) {
    const GtCode code = run([&] { p->push_segment(*seg, vel, acc, 0.0, false, /*auto_end=*/true); });
    r_.pushed += code == GtCode::Success;
    return code;
  }
  machine::Card& card = gt_.card();
  if (r_.buffer && p->has_breakpoint()) {
    // a stopped buffer: a path command runs at once as a single line, the buffer waits (L1938, V64)
    if (seg->kind() != motion::SegmentKind::Line || p->busy()) return refuse();
    return run([&] {
      card.modes().before_group_start(machine::kGtCrdSlot);
      p->move_immediate(seg->end(), vel, acc);
    });
  }
  if (p->busy() || p->running() || p->fifo_size() || p->window_size()) return refuse();  // one at a time (L1800)
  const GtCode code = run([&] {
    p->clear();
    p->push_segment(*seg, vel, acc, 0.0, false, false, /*stop_at_end=*/true);
    card.modes().before_group_start(machine::kGtCrdSlot);
    p->start();
  });
  if (code == GtCode::Success) r_.buffer = r_.started = false;  // immediate (single-segment) mode again (V64)
  return code;
}

GtCode GtCrdList::line(const std::vector<double>& point) {
  return path_command([&](const CrdPoint& t, int dim) {
    if (static_cast<int>(point.size()) > dim) throw std::invalid_argument("GT line: more coordinates than mapped");
    CrdPoint end = t;
    std::copy(point.begin(), point.end(), end.begin());
    return PathSegmentGeometry::line(t, end, dim);
  });
}

GtCode GtCrdList::arc_center_angle(motion::ArcPlane plane, double center_1, double center_2, double angle_deg) {
  return path_command([&](const CrdPoint& t, int dim) {
    return PathSegmentGeometry::arc_center_angle(t, dim, plane, center_1, center_2, angle_deg);
  });
}

GtCode GtCrdList::arc_end_radius(motion::ArcPlane plane, double end_1, double end_2, double radius,
                                 double direction) {
  if (!(finite_in(end_1, kPosMin, kPosMax) && finite_in(end_2, kPosMin, kPosMax) &&
        finite_in(radius, -2147483648.0, 2147483648.0)))
    return GtCode::ParameterError;
  if (direction != 1.0 && direction != -1.0) return GtCode::ParameterError;
  return path_command([&](const CrdPoint& t, int dim) {
    CrdPoint end = t;
    end[motion::plane_axis(plane, 0)] = end_1;
    end[motion::plane_axis(plane, 1)] = end_2;
    return PathSegmentGeometry::arc_end_radius(t, end, dim, plane, radius, direction == 1.0);
  });
}

GtCode GtCrdList::start_list() {
  motion::PathGenerator* p = path();
  if (p == nullptr || p->busy() || p->running()) return refuse();
  const GtCode code = run([&] { p->clear(); });
  if (code == GtCode::Success) {
    r_.buffer = r_.open = true;
    r_.mv = r_.started = false;
    r_.pushed = r_.mv_pushed = 0;
  }
  return code;
}

GtCode GtCrdList::move_start_point(const std::vector<double>& point, double vel, double acc) {
  if (!r_.open || r_.mv) return refuse(13);  // Mv* once after StrtList (L1843): an Mv* error, bit 13 (L476)
  if (!finite_in(vel, 0, kSynMax) || !finite_in(acc, 0, kSynMax) || vel == 0 || acc == 0)
    return refuse(13, GtCode::ParameterError);  // bad Mv* parameters: 7 with bit 13
  motion::PathGenerator* p = path();
  if (p == nullptr) return GtCode::CommandError;
  const CrdPoint t = p->tail();
  const int dim = p->coords().dim();
  if (static_cast<int>(point.size()) > dim) return GtCode::ParameterError;
  CrdPoint end = t;
  std::copy(point.begin(), point.end(), end.begin());
  const bool moves = end != t;
  const GtCode code = run([&] {
    if (moves) p->push_segment(PathSegmentGeometry::line(t, end, dim), vel, acc, 0.0, false, false, true);
  }, /*mv=*/true);
  if (code == GtCode::Success) {  // the Mv vel/acc become the defaults (L1845)
    r_.mv = true;
    r_.vel = vel;
    r_.acc = acc;
    r_.mv_pushed = moves ? 1 : 0;
  }
  return code;
}

GtCode GtCrdList::end_list() {
  if (!r_.open) return refuse();
  r_.open = false;
  return GtCode::Success;
}

GtCode GtCrdList::add_list() {
  if (r_.open || !r_.buffer) return refuse();
  r_.open = true;
  return GtCode::Success;
}

GtCode GtCrdList::start_motion() {
  if (!r_.buffer || !r_.mv) return refuse();
  motion::PathGenerator* p = path();
  if (p == nullptr) return GtCode::CommandError;
  if (p->busy() || (p->running() && !p->stopped())) return refuse();
  const GtCode code = run([&] {
    gt_.card().modes().before_group_start(machine::kGtCrdSlot);
    p->start();
  });
  if (code == GtCode::Success) r_.started = true;
  return code;
}

GtCode GtCrdList::stop(bool abrupt) {
  motion::PathGenerator* p = path();
  if (p == nullptr) return refuse();
  const GtCode code = run([&] { p->stop(abrupt); });
  if (code == GtCode::Success) r_.open = false;  // both stops close the buffer (L1936)
  return code;
}

GtCode GtCrdList::set_auto_stop(bool on) {
  r_.au_stp = on;
  return GtCode::Success;
}

long long GtCrdList::motion_number() const {
  const motion::PathGenerator* p = path_if_set_up();
  if (!r_.buffer || p == nullptr) return 0;
  long long n = p->state().segments_done - r_.mv_pushed + (p->busy() && p->state().speed > 0 ? 1 : 0);
  n = std::max(0LL, std::min(n, r_.pushed));
  return n > 0 ? (n - 1) % 32767 + 1 : 0;
}

std::uint16_t GtCrdList::status() const {
  CrdStatusInputs in;
  in.last_command_error = r_.error;
  in.auto_stop_on = r_.au_stp;
  const motion::PathGenerator* p = path_if_set_up();
  if (p == nullptr) return gt_crd_status(in);
  in.moving = p->busy() || (r_.buffer && r_.started && r_.open && !p->stopped());
  in.buffer_closed = !r_.open;
  in.segment_complete = !p->busy();
  in.immediate_mode = !r_.buffer;
  in.fault_stopped = gt_.card().modes_if_any()->hosted(machine::kGtCrdSlot).fault_stopped;
  in.buffer_empty = p->fifo_size() == 0 && p->window_size() == 0 && !p->busy();
  in.buffer_started = r_.started;
  return gt_crd_status(in);
}

GtCode GtCrdList::breakpoint(std::optional<std::vector<double>>& point) {
  point.reset();
  const motion::PathGenerator* p = path();
  if (p == nullptr) return GtCode::CommandError;
  if (p->has_breakpoint())
    point = std::vector<double>(p->breakpoint().begin(), p->breakpoint().begin() + p->coords().dim());
  return GtCode::Success;
}

}  // namespace servobench::vendor::googol
