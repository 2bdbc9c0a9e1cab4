#include "servobench/motion/follow_ex.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/motion/generator.hpp"

namespace servobench::motion {

namespace {
constexpr const char* kSetup = "FollowExSetup";

std::string idx(const char* name, std::size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; }
}  // namespace

void FollowExSetup::validate() const {
  check_integer(kSetup, "dir", dir, -1, 1, "0 both, 1 positive, -1 negative; iDEABOX L6185");
  check_integer(kSetup, "master_type", master_type, 1, 3, "1 encoder, 2 profile, 3 axis; iDEABOX L7345-7363");
  check_integer(kSetup, "master_item", master_item, 0, 1, "0 planned, 1 encoder; iDEABOX L7345-7363");
  check_integer(kSetup, "memory", memory, 0, 2, "0: 16, 1: 512, 2: dynamic segments per FIFO; iDEABOX L489-493");
  check_integer(kSetup, "max_segment", max_segment, 0, 2147483647.0, "0 = not set; iDEABOX L497-501, L7254");
  if (memory == 2 && max_segment < 1)
    throw_invalid(kSetup, "max_segment", max_segment,
                  "must be set (1..2147483647) for the dynamic memory = 2 (GT_SetFollowExMaxSegment before "
                  "GT_SetFollowMemoryEx, iDEABOX L497-501)");
  check_integer(kSetup, "event", event, 1, 2, "1 START, 2 PASS; iDEABOX L536-542, L7224-7240");
  check_integer(kSetup, "master_dir", master_dir, -1, 1, "1 positive, -1 negative; iDEABOX L7224-7240");
  if (master_dir == 0)
    throw_invalid(kSetup, "master_dir", master_dir, "must be 1 or -1 (iDEABOX L7224-7240)");
  check_integer(kSetup, "event_pos", event_pos, -2147483648.0, 2147483647.0, "pulse, long; iDEABOX L7212");
  check_integer(kSetup, "loop", loop, -32768, 32767, "short, < 1 = infinite; iDEABOX L7287-7302");
}

long FollowExSetup::fifo_capacity() const {
  if (memory == 0) return 16;
  if (memory == 1) return 512;
  return static_cast<long>(max_segment);
}

double FollowCam::slave_at(double x) const {
  if (pieces.empty() || x <= 0.0) return 0.0;
  if (x >= length) return slave_length;
  auto it = std::upper_bound(pieces.begin(), pieces.end(), x,
                             [](double v, const PvtPiece& pc) { return v < pc.t0_ms; });
  const PvtPiece& pc = *(it - 1);
  return pc.seg.at(std::min(x - pc.t0_ms, pc.seg.duration)).pos;
}

double FollowCam::ratio_at(double x) const {
  if (pieces.empty()) return 0.0;
  x = std::clamp(x, 0.0, length);
  auto it = std::upper_bound(pieces.begin(), pieces.end(), x,
                             [](double v, const PvtPiece& pc) { return v < pc.t0_ms; });
  if (it == pieces.begin()) it = pieces.begin() + 1;
  const PvtPiece& pc = *(it - 1);
  return pc.seg.at(std::min(x - pc.t0_ms, pc.seg.duration)).vel * master_sign;
}

FollowCam plan_follow_cam(const std::vector<FollowSegmentData>& segs, double entry_ratio) {
  FollowCam cam;
  if (segs.empty()) return cam;
  const double s = segs.front().master >= 0 ? 1.0 : -1.0;
  cam.master_sign = s;
  double x = 0.0, p = 0.0, prev_r1 = 0.0;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const auto& d = segs[i];
    const double L = std::fabs(d.master);
    const double chord = d.slave / d.master;  // dS/dM
    double r0 = 0, r1 = 0;
    if (d.explicit_ratios) {
      r0 = d.r0;
      r1 = d.r1;
    } else {
      switch (d.type) {
        case FollowSegmentType::Normal:
          r0 = i == 0 ? 0.0 : prev_r1;
          r1 = 2.0 * chord - r0;
          break;
        case FollowSegmentType::Continue:
          r0 = i == 0 ? entry_ratio : prev_r1;
          r1 = 2.0 * chord - r0;
          break;
        case FollowSegmentType::Even:
          r0 = r1 = chord;
          break;
        case FollowSegmentType::Stop:
          r0 = 2.0 * chord;
          r1 = 0.0;
          break;
      }
    }
    const double rho0 = r0 * s, rho1 = r1 * s;  // d(slave)/d(travel)
    if (d.explicit_ratios) {                    // Hermite cubic (Complete)
      const double D = d.slave;
      const double b = 3.0 * D / (L * L) - (2.0 * rho0 + rho1) / L;
      const double a = (rho0 + rho1) / (L * L) - 2.0 * D / (L * L * L);
      cam.pieces.push_back({x, Segment{L, p, rho0, 2.0 * b, 6.0 * a}});
    } else {
      append_percent_ramp(cam.pieces, x, L, p, rho0, rho1, d.percent / 100.0);
    }
    x += L;
    p += d.slave;
    cam.segment_end_x.push_back(x);
    cam.ratio_begin.push_back(r0);
    cam.ratio_end.push_back(r1);
    prev_r1 = r1;
  }
  cam.length = x;
  cam.slave_length = p;
  return cam;
}

std::vector<FollowSegmentData> follow_complete_segments(const std::vector<double>& master,
                                                        const std::vector<double>& slave, double ratio_begin,
                                                        double ratio_end) {
  const char* owner = "FollowDataComplete";
  const std::size_t n = master.size();
  if (n < 2)
    throw std::invalid_argument(std::string(owner) + ".n = " + std::to_string(n) +
                                " is outside the allowed range 2.. (knots; the first is the curve start)");
  if (slave.size() != n)
    throw std::invalid_argument(std::string(owner) + ".slave has " + std::to_string(slave.size()) +
                                " values; expected " + std::to_string(n) + " (one per master value)");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(master[i])) throw_invalid(owner, idx("master", i).c_str(), master[i], "is not a finite number");
    if (!std::isfinite(slave[i])) throw_invalid(owner, idx("slave", i).c_str(), slave[i], "is not a finite number");
  }
  if (!std::isfinite(ratio_begin)) throw_invalid(owner, "ratio_begin", ratio_begin, "is not a finite number");
  if (!std::isfinite(ratio_end)) throw_invalid(owner, "ratio_end", ratio_end, "is not a finite number");
  const double s = master[1] >= master[0] ? 1.0 : -1.0;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = s * (master[i] - master[0]);
    if (i > 0 && !(x[i] > x[i - 1]))
      throw_invalid(owner, idx("master", i).c_str(), master[i],
                    "must continue the direction of master[0] -> master[1] (the master values are monotonic)");
  }
  const auto rho = pvt_complete_velocities(x, slave, ratio_begin * s, ratio_end * s);
  std::vector<FollowSegmentData> out;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    FollowSegmentData d;
    d.master = master[i + 1] - master[i];
    d.slave = slave[i + 1] - slave[i];
    d.explicit_ratios = true;
    d.r0 = rho[i] * s;
    d.r1 = rho[i + 1] * s;
    out.push_back(d);
  }
  return out;
}

FollowEx::FollowEx(const FollowExSetup& setup, double slave_pos) : setup_(setup) {
  setup_.validate();
  if (!std::isfinite(slave_pos)) throw_invalid("FollowEx", "slave_pos", slave_pos, "must be a finite number");
  state_.pos = slave_pos;
}

void FollowEx::configure(const FollowExSetup& setup) {
  setup.validate();
  if (running_) throw MotionCommandRefused("FollowEx: the setup cannot change while following (return code 1)");
  if (setup.fifo_capacity() != setup_.fifo_capacity() && (!fifo_data_[0].empty() || !fifo_data_[1].empty()))
    throw MotionCommandRefused("GT_SetFollowMemoryEx: the FIFO size is set before data is written (return code 1; "
                               "iDEABOX L514)");
  setup_ = setup;
}

void FollowEx::check_fifo(double fifo) const {
  check_integer("FollowEx", "fifo", fifo, 0, 1, "two FIFOs per axis; iDEABOX L4837-4916");
}

void FollowEx::check_writable(int fifo, long n) const {
  const long cap = setup_.fifo_capacity();
  if (size(fifo) + n > cap)
    throw MotionCommandRefused("FollowEx FIFO " + std::to_string(fifo) + " has " + std::to_string(space(fifo)) +
                               " free segments of " + std::to_string(cap) + ", " + std::to_string(n) +
                               " needed: the data is lost (return code 1; iDEABOX L532-534, L4687, L4740)");
}

long FollowEx::size(int fifo) const {
  check_fifo(fifo);
  return static_cast<long>(fifo_data_[static_cast<std::size_t>(fifo)].size());
}

long FollowEx::space(int fifo) const { return setup_.fifo_capacity() - size(fifo); }

void FollowEx::data_percent(double master, double slave, FollowSegmentType type, double percent, int fifo) {
  const char* owner = "FollowDataPercent";
  check_fifo(fifo);
  check_integer(owner, "master", master, -2147483648.0, 2147483647.0, "pulse, long, cumulative; iDEABOX L4712");
  if (!std::isfinite(slave)) throw_invalid(owner, "slave", slave, "is not a finite number");
  check_integer(owner, "type", static_cast<double>(static_cast<int>(type)), 0, 3,
                "NORMAL 0, EVEN 1, STOP 2, CONTINUE 3; iDEABOX L4718-4726");
  check_integer(owner, "percent", percent, 0, 100, "short; iDEABOX L4728");
  const auto k = static_cast<std::size_t>(fifo);
  const double dm = master - last_master_[k];
  if (dm == 0.0)
    throw_invalid(owner, "master", master,
                  "repeats the previous value written to FIFO " + std::to_string(fifo) +
                      ": the values are cumulative, a segment needs a master displacement (decision M30)");
  auto& data = fifo_data_[k];
  if (!data.empty() && (dm > 0) != (data.front().master > 0))
    throw_invalid(owner, "master", master,
                  "reverses the direction of the FIFO's earlier segments (a cam's master values are monotonic)");
  check_writable(fifo, 1);
  FollowSegmentData d;
  d.master = dm;
  d.slave = slave - last_slave_[k];
  d.type = type;
  d.percent = percent;
  data.push_back(d);
  last_master_[k] = master;
  last_slave_[k] = slave;
  if (running_ && fifo == fifo_) cam_ = plan_follow_cam(data, cam_.ratio_begin.empty() ? 0.0 : cam_.ratio_begin[0]);
}

void FollowEx::data_complete(const std::vector<double>& master, const std::vector<double>& slave,
                             double ratio_begin, double ratio_end, int fifo) {
  check_fifo(fifo);
  auto segs = follow_complete_segments(master, slave, ratio_begin, ratio_end);
  const auto k = static_cast<std::size_t>(fifo);
  auto& data = fifo_data_[k];
  if (!data.empty() && (segs.front().master > 0) != (data.front().master > 0))
    throw_invalid("FollowDataComplete", "master[1]", master[1],
                  "reverses the direction of the FIFO's earlier segments (a cam's master values are monotonic)");
  check_writable(fifo, static_cast<long>(segs.size()));
  data.insert(data.end(), segs.begin(), segs.end());
  double dm = 0, ds = 0;
  for (const auto& s : segs) dm += s.master, ds += s.slave;
  last_master_[k] += dm;
  last_slave_[k] += ds;
  if (running_ && fifo == fifo_) cam_ = plan_follow_cam(data, cam_.ratio_begin.empty() ? 0.0 : cam_.ratio_begin[0]);
}

void FollowEx::clear(int fifo) {
  check_fifo(fifo);
  if (running_ && (fifo == fifo_ || switch_pending_))
    throw MotionCommandRefused("FollowClearEx: refused, FIFO " + std::to_string(fifo) +
                               " is in use by the moving axis (return code 1; iDEABOX L80, L411, L4619)");
  const auto k = static_cast<std::size_t>(fifo);
  fifo_data_[k].clear();
  last_master_[k] = 0.0;
  last_slave_[k] = 0.0;
}

void FollowEx::activate(int fifo, double entry_ratio) {
  fifo_ = fifo;
  cam_ = plan_follow_cam(fifo_data_[static_cast<std::size_t>(fifo)], entry_ratio);
}

void FollowEx::start(double master_pos, int fifo) {
  check_fifo(fifo);
  if (!std::isfinite(master_pos)) throw_invalid("FollowEx", "master_pos", master_pos, "must be a finite number");
  if (running_) throw MotionCommandRefused("FollowStartEx: refused, the axis is moving (return code 1; iDEABOX L4997)");
  if (fifo_data_[static_cast<std::size_t>(fifo)].empty())
    throw MotionCommandRefused("FollowStartEx: FIFO " + std::to_string(fifo) +
                               " is empty (return code 1; iDEABOX L4997-5003)");
  activate(fifo, 0.0);
  running_ = true;
  waiting_ = setup_.event == 2;
  switch_pending_ = false;
  prev_master_ = master_pos;
  x_ = 0.0;
  slave_base_ = state_.pos;
  passes_done_ = 0;
  state_ = {state_.pos, 0.0, 0.0, 0.0};
}

void FollowEx::switch_fifo() {
  if (!running_)
    throw MotionCommandRefused("FollowSwitchEx: only while moving (return code 1; iDEABOX L5291-5293)");
  const int other = 1 - fifo_;
  if (fifo_data_[static_cast<std::size_t>(other)].empty())
    throw MotionCommandRefused("FollowSwitchEx: the target FIFO " + std::to_string(other) +
                               " is empty (return code 1; iDEABOX L5291-5293)");
  switch_pending_ = true;
}

void FollowEx::stop() {
  running_ = false;
  waiting_ = false;
  switch_pending_ = false;
  state_ = {state_.pos, 0.0, 0.0, 0.0};
}

long long FollowEx::reported_pos() const { return std::llround(state_.pos); }

double FollowEx::ratio() const { return running_ && !waiting_ ? cam_.ratio_at(x_) : 0.0; }

const MotionState& FollowEx::step(double master_pos) {
  if (!std::isfinite(master_pos)) throw_invalid("FollowEx", "master_pos", master_pos, "must be a finite number");
  double pos = state_.pos;
  if (running_) {
    double dm = master_pos - prev_master_;
    bool follow = true;
    if (waiting_) {
      const double e = setup_.event_pos;
      const bool crossed = setup_.master_dir > 0 ? (prev_master_ < e && master_pos >= e)
                                                 : (prev_master_ > e && master_pos <= e);
      if (crossed) {
        waiting_ = false;
        dm = master_pos - e;
      } else {
        follow = false;
      }
    }
    prev_master_ = master_pos;
    if (follow) {
      if (setup_.dir > 0) dm = std::max(dm, 0.0);
      if (setup_.dir < 0) dm = std::min(dm, 0.0);
      x_ += dm * cam_.master_sign;
      const long loop = static_cast<long>(setup_.loop);
      while (x_ >= cam_.length && cam_.length > 0.0) {
        const double end_ratio = cam_.ratio_end.back();
        if (switch_pending_) {  // decision M33: at the end of the pass
          slave_base_ += cam_.slave_length;
          x_ -= cam_.length;
          switch_pending_ = false;
          passes_done_ = 0;
          activate(1 - fifo_, end_ratio);
          continue;
        }
        ++passes_done_;
        if (loop >= 1 && passes_done_ >= loop) {
          x_ = cam_.length;
          running_ = false;
          break;
        }
        slave_base_ += cam_.slave_length;
        x_ -= cam_.length;
      }
      while (x_ < 0.0 && passes_done_ > 0) {  // a bidirectional master going back into the previous pass
        --passes_done_;
        slave_base_ -= cam_.slave_length;
        x_ += cam_.length;
      }
      pos = slave_base_ + cam_.slave_at(x_);
    }
  }
  const double vel = pos - state_.pos;
  const double acc = vel - state_.vel;
  state_ = {pos, vel, acc, acc - state_.acc};
  return state_;
}

}  // namespace servobench::motion
