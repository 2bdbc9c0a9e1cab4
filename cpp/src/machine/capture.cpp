#include "servobench/machine/capture.hpp"

#include <string>

namespace servobench::machine {

const char* to_string(CaptureTrigger trigger) {
  switch (trigger) {
    case CaptureTrigger::None: return "none";
    case CaptureTrigger::Home: return "home";
    case CaptureTrigger::Index: return "index";
    case CaptureTrigger::Probe: return "probe";
  }
  return "?";
}

void CaptureUnit::arm(CaptureTrigger trigger) {
  if (trigger == CaptureTrigger::None) {
    armed_ = CaptureTrigger::None;
    return;
  }
  if (armed_ != CaptureTrigger::None)
    throw motion::MotionCommandRefused(std::string("capture: refused, already armed for ") + to_string(armed_) +
                                       " (GT command status bit 8, GT L465-471)");
  if (captured_)
    throw motion::MotionCommandRefused(
        "capture: refused, the captured flag (status bit 3) is still set; clear it first (GT_ClrSts, GT L2017, "
        "command status bit 7)");
  armed_ = trigger;
}

bool CaptureUnit::update(const motion::SignalEvent& home, const motion::SignalEvent& index, bool probe,
                         double probe_pos) {
  bool hit = false;
  double pos = 0.0;
  switch (armed_) {
    case CaptureTrigger::None: return false;
    case CaptureTrigger::Home: hit = home.rose; pos = home.edge_pos; break;
    case CaptureTrigger::Index: hit = index.rose; pos = index.edge_pos; break;
    case CaptureTrigger::Probe: hit = probe; pos = probe_pos; break;
  }
  if (!hit) return false;
  value_ = pos;
  source_ = armed_;
  armed_ = CaptureTrigger::None;
  captured_ = true;
  return true;
}

}  // namespace servobench::machine
