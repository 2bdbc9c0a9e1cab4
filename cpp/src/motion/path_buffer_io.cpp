// The path generator's buffered non-motion commands (BufIO, BufDelay, BufDA, BufMove, BufGear, user segment
// numbers, BufLmts, BufSetStopIo) and its stop inputs (motion/path_generator.hpp; GUC L625-700).
#include "servobench/motion/path_generator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "path_detail.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/motion/check.hpp"

namespace servobench::motion {

using detail::check_open;

void PathGenerator::buf_io(int io_type, std::uint32_t mask, std::uint32_t value) {
  admit();
  check_integer("BufIO", "do_type", io_type, 0, 2, "0 GPO, 1 drive enable, 2 alarm clear; GUC L588-597");
  check_integer("BufIO", "mask", mask, 0, 65535, "16 channels; GUC L588-597");
  check_integer("BufIO", "value", value, 0, 65535, "16 channels; GUC L588-597");
  PathCommand c;
  c.type = PathCommandType::Io;
  c.io_type = io_type;
  c.mask = mask;
  c.value = value;
  enqueue(std::move(c));
}

void PathGenerator::buf_delay(double ms) {
  admit();
  check_integer("BufDelay", "delay_ms", ms, 0, 16383, "ms; GUC L598-602, iDEABOX L4212");
  PathCommand c;
  c.type = PathCommandType::Delay;
  c.delay_ms = ms;
  enqueue(std::move(c));
  tail_stop_next_ = true;
}

void PathGenerator::buf_da(int channel, double value) {
  admit();
  check_integer("BufDA", "channel", channel, 1, 8, "GUC L603-608");
  check_integer("BufDA", "value", value, -32768, 32767, "counts, -10..+10 V; GUC L603-608");
  PathCommand c;
  c.type = PathCommandType::Da;
  c.channel = channel;
  c.da = value;
  enqueue(std::move(c));
}

void PathGenerator::buf_move(int axis, double pos, double vel, double acc, bool modal) {
  admit();
  check_integer("BufMove", "axis", axis, 1, 64, "GUC L646-656, iDEABOX L4373");
  for (int a : coords_.axes())
    if (a == axis) throw_invalid("BufMove", "axis", axis, "is an axis of the coordinate system (GUC L1013)");
  check_integer("BufMove", "pos", pos, -2147483648.0, 2147483647.0, "absolute, pulse; GUC L646-656");
  check_open("BufMove", "vel", vel, 0, 1e9, "pulse/ms, > 0; GUC L646-656");
  check_open("BufMove", "acc", acc, 0, 1e9, "pulse/ms^2, > 0; GUC L646-656");
  aux(axis);
  PathCommand c;
  c.type = PathCommandType::Move;
  c.axis = axis;
  c.pos = pos;
  c.vel = vel;
  c.acc = acc;
  c.modal = modal;
  enqueue(std::move(c));
  if (modal) tail_stop_next_ = true;
}

void PathGenerator::buf_gear(int axis, double distance) {
  admit();
  check_integer("BufGear", "axis", axis, 1, 64, "GUC L657-661, iDEABOX L4234-4248");
  for (int a : coords_.axes())
    if (a == axis) throw_invalid("BufGear", "axis", axis, "is an axis of the coordinate system (GUC L657-661)");
  check_integer("BufGear", "pos", distance, -2147483648.0, 2147483647.0, "relative, pulse; GUC L657-661");
  aux(axis);
  PathCommand c;
  c.type = PathCommandType::Gear;
  c.axis = axis;
  c.pos = distance;
  enqueue(std::move(c));
}

void PathGenerator::set_user_seg_num(long long n) {
  admit();
  check_integer("SetUserSegNum", "seg_num", static_cast<double>(n), -2147483648.0, 2147483647.0, "GUC L662-665");
  PathCommand c;
  c.type = PathCommandType::UserSegNum;
  c.user_seg = n;
  enqueue(std::move(c));
}

void PathGenerator::buf_lmts(int axis, int limit_type, bool on) {
  admit();
  const char* o = on ? "BufLmtsOn" : "BufLmtsOff";
  check_integer(o, "axis", axis, 1, 16, "GUC L609-624: 1..8; iDEABOX L4292-4300: 1..12 (core 1), 1..16 (core 2)");
  check_integer(o, "limit_type", limit_type, -1, 1, "0 positive, 1 negative, -1 both; GUC L609-624, iDEABOX L4292-4300");
  PathCommand c;
  c.type = PathCommandType::Lmts;
  c.axis = axis;
  c.limit_type = limit_type;
  c.limits_on = on;
  enqueue(std::move(c));
}

namespace {
void check_input(const char* o, int input_type, int index) {
  check_integer(o, "input_type", input_type, 0, 4, "0 +limit, 1 -limit, 2 alarm, 3 home, 4 GPI; GUC L625-645");
  check_integer(o, "input_index", index, 1, input_type == 4 ? 16 : 8,
                input_type == 4 ? "GPI 1..16; GUC L625-645 (OCR prints [1,6])" : "1..8; GUC L625-645");
}
}  // namespace

void PathGenerator::buf_set_stop_io(int axis, int stop_type, int input_type, int input_index) {
  admit();
  const char* o = "BufSetStopIo";
  check_integer(o, "axis", axis, 1, 8, "GUC L625-645");
  check_integer(o, "stop_type", stop_type, 0, 1, "0 emergency, 1 smooth; GUC L625-645");
  check_input(o, input_type, input_index);
  PathCommand c;
  c.type = PathCommandType::StopIo;
  c.axis = axis;
  c.stop_io = StopIoMapping{true, stop_type, input_type, input_index};
  enqueue(std::move(c));
}

void PathGenerator::set_input(int input_type, int index, bool active) {
  check_input("PathGenerator.set_input", input_type, index);
  auto& w = inputs_[static_cast<std::size_t>(input_type)];
  const std::uint32_t bit = 1u << (index - 1);
  w = active ? (w | bit) : (w & ~bit);
}

bool PathGenerator::input(int input_type, int index) const {
  check_input("PathGenerator.input", input_type, index);
  return (inputs_[static_cast<std::size_t>(input_type)] >> (index - 1)) & 1u;
}

const StopIoMapping& PathGenerator::stop_io(int axis) const {
  check_integer("PathGenerator.stop_io", "axis", axis, 1, 8, "GUC L625-645");
  return stop_io_[static_cast<std::size_t>(axis - 1)];
}

void PathGenerator::relocate(const CrdPoint& pos) {
  for (double v : pos)
    if (!std::isfinite(v)) throw_invalid("PathGenerator", "position", v, "is not a finite coordinate");
  if (busy()) refuse("PathGenerator.relocate: the path is moving");
  st_.pos = pos;
  if (fifo_.empty() && window_.empty() && !cur_valid_ && !has_brk_) {
    tail_ = pos;
    tail_u_valid_ = false;
  }
}

void PathGenerator::check_stop_inputs() {
  for (std::size_t k = 0; k < stop_io_.size(); ++k) {
    const StopIoMapping& m = stop_io_[k];
    if (!m.armed) continue;
    const std::uint32_t bit = 1u << (m.input_index - 1);
    bool active = (inputs_[static_cast<std::size_t>(m.input_type)] & bit) != 0;
    // A limit input counts only while that limit is enabled (BufLmtsOn / BufLmtsOff, decision C28).
    if (m.input_type == 0) active = active && (st_.limits_pos & bit);
    if (m.input_type == 1) active = active && (st_.limits_neg & bit);
    if (!active) continue;
    const int axis = static_cast<int>(k) + 1;
    const bool abrupt = m.stop_type == 0;
    bool in_crd = false;
    for (int a : coords_.axes()) in_crd = in_crd || a == axis;
    if (in_crd) {
      if ((running() || act_ == Act::Immediate) && !stop_at_rest_) {
        st_.io_stop_axis = axis;
        stop(abrupt);
      }
      continue;
    }
    auto it = aux_.find(axis);
    if (it == aux_.end() || !it->second.gen->moving() || it->second.gen->stopping()) continue;
    st_.io_stop_axis = axis;
    if (abrupt) {
      it->second.gen->abrupt_stop();
    } else {
      it->second.gen->smooth_stop();
    }
    // A modal move aborted by its stop input halts the FIFO (GUC L1055, iDEABOX L2344-2348).
    if (act_ == Act::WaitMove && wait_axis_ == axis) {
      act_ = Act::None;
      enter_stopped();
    }
  }
}

}  // namespace servobench::motion
