#include "servobench/motion/crd_fifo_pair.hpp"

#include <algorithm>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

namespace {
PathSetup with_tolerance(PathSetup s, double tol) {
  check_range("CrdFifoPair", "resume_tolerance", tol, 0, 1e6, "unit per coordinate; GUC L1005, decision C26");
  s.return_to_stop_point = false;  // GUC/iDEABOX: resume only at the breakpoint
  s.resume_tolerance = tol;
  return s;
}

void refuse(const std::string& what) { throw MotionCommandRefused(what + " (return code 1)"); }
}  // namespace

CrdFifoPair::CrdFifoPair(const CoordSystem& coords, const PathSetup& setup, const CrdPoint& start,
                         double resume_tolerance)
    : g_{PathGenerator(coords, with_tolerance(setup, resume_tolerance), start),
         PathGenerator(coords, with_tolerance(setup, resume_tolerance), start)} {
  g_[0].set_gate([this](PathGateEvent e) { gate(0, e); });
  g_[1].set_gate([this](PathGateEvent e) { gate(1, e); });
}

void CrdFifoPair::follow(int k) {
  // FIFO k takes over the coordinate position if it is at rest (its breakpoint, if any, is kept).
  PathGenerator& g = g_[static_cast<std::size_t>(k)];
  if (k != active_ && !g.busy()) g.relocate(g_[static_cast<std::size_t>(active_)].state().pos);
}

void CrdFifoPair::gate(int k, PathGateEvent e) {
  PathGenerator& other = g_[static_cast<std::size_t>(1 - k)];
  switch (e) {
    case PathGateEvent::Push:
      if (k == 1) {
        if (other.busy() || other.running())
          refuse("CrdFifoPair: data may go to FIFO1 only while FIFO0 is stopped (GUC L1003, iDEABOX L1640)");
        follow(1);
      }
      break;
    case PathGateEvent::Start:
      if (other.busy() || other.running())
        refuse("CrdFifoPair: FIFO" + std::to_string(1 - k) + " is moving the coordinate system (iDEABOX L4558-4566)");
      follow(k);
      break;
    case PathGateEvent::Started:
      if (k == 0) {
        other.clear();  // a suspended FIFO1 is lost (GUC L1003, iDEABOX L1640-1642)
      } else {
        other.stop(true);  // FIFO0 waits for its own GT_CrdStart (decision C25)
      }
      active_ = k;
      break;
  }
}

PathGenerator& CrdFifoPair::fifo(int k) {
  check_integer("CrdFifoPair", "fifo", k, 0, 1, "GUC L684-690");
  if (k == 1 && !g_[0].busy() && !g_[0].running() && g_[1].fifo_size() == 0 && g_[1].window_size() == 0 &&
      !g_[1].has_breakpoint())
    follow(1);
  return g_[static_cast<std::size_t>(k)];
}

const PathGenerator& CrdFifoPair::fifo(int k) const {
  check_integer("CrdFifoPair", "fifo", k, 0, 1, "GUC L684-690");
  return g_[static_cast<std::size_t>(k)];
}

void CrdFifoPair::start(int k) { fifo(k).start(); }

void CrdFifoPair::stop(bool abrupt) { g_[static_cast<std::size_t>(active_)].stop(abrupt); }

const PathState& CrdFifoPair::step() {
  g_[0].step();
  g_[1].step();
  return state();
}

std::vector<int> CrdFifoPair::aux_axes() const {
  std::vector<int> v = g_[0].aux_axes();
  for (int a : g_[1].aux_axes())
    if (std::find(v.begin(), v.end(), a) == v.end()) v.push_back(a);
  std::sort(v.begin(), v.end());
  return v;
}

double CrdFifoPair::aux_position(int axis) const {
  const auto a0 = g_[0].aux_axes();
  if (std::find(a0.begin(), a0.end(), axis) != a0.end()) return g_[0].aux_position(axis);
  return g_[1].aux_position(axis);
}

}  // namespace servobench::motion

namespace servobench::motion {
PathRecording record(CrdFifoPair& pair, std::size_t ticks, bool until_done) {
  return record_path(pair, ticks, until_done);
}
}  // namespace servobench::motion
