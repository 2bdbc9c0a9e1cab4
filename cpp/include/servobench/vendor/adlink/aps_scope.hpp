// ApsScope: the ADLINK PCI-8254/8258 host-side scope registers as a card module (machine/card_hooks.hpp): the data
// sampling (APS_set_sampling_param / APS_wait_trigger_sampling[_async] / APS_get_sampling_count, manual seed 004
// L3544-3665, Tables 4-5 and 4-6 L3558-3600), the position-compare trigger parameters (APS_set_trigger_param,
// L3348-3435) and the compare timer (TIMR_*, L3363-3378). Decisions V71-V85, V128, AF15; session 11 AV1-AV6.
//
// The module keeps the registers and the sampling run; the machinery is the kernel's: the card's sampler
// (machine/sampler.hpp) samples the channels, its position compare (machine/position_compare.hpp) emits the
// trigger pulses. Every function returns the APS library's code (return_code.hpp) and never throws.
//
// Units: sampling rate in servo ticks per sample; SAMP_PA_LEVEL in the trigger channel's unit (pulse, pulse/s,
// mV, bits); trigger pulse width TGR_TRGx_PWD in 100 ns; the timer counts TIMR_ITV servo ticks per count.
// A sample (STR_SAMP_DATA_4CH, V78): the card tick and the four channels in their units (pulse, pulse/s, mV,
// bits), whole numbers for the I32 sources.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/machine/sampler.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

// Sampling parameter numbers (APS_define.h).
constexpr int kSampRate = 0x0, kSampEdge = 0x2, kSampLevel = 0x3, kSampTrigCh = 0x5, kSampSrcCh0 = 0x10;

// One sampling source of Tables 4-5 / 4-6: the card sampler's signal, the factor to the APS unit, whether the
// source is an I32 (whole numbers), the bit of a status word (-1: the whole value).
struct ApsSampleSource {
  const char* signal;   // machine::sample_signal_from name
  double scale;         // APS value = signal x scale (x 1/Ts when per_second)
  bool per_second;      // pulse/tick -> pulse/s
  bool integer;         // an I32 source: rounded to whole numbers
  int bit;              // a one-bit source of MSTS/MIO, or -1
};
// The source of code src (the low byte of SAMP_PA_SRC_CHx), nullptr when the card does not sample it (gantry,
// PWM, VAO, point-table sources).
const ApsSampleSource* aps_sample_source(int src);

// One sample of the sampling block (STR_SAMP_DATA_4CH {I32 tick; I32 data[4]}; int64 and F64 here, V78).
struct ApsSample {
  std::int64_t tick;
  double data[4];
};

class ApsScope : public machine::CardHooks {
 public:
  explicit ApsScope(machine::Card& card);

  // The power-on registers (APS_initial): SAMP_PA_RATE = the ticks of 1 ms (L3548), SAMP_PA_EDGE 2 (no trigger,
  // V80), sources COM_POS, FBK_POS, ERROR_POS, CONTROL_VOL of axis 0; trigger parameters 0 but TCMPx_DIR 1,
  // LCMP1/TCMP1 on axis 1, TRGx_PWD 1 (100 ns); the timer at 0, stopped; no sampling run.
  void power_on();

  // -- data sampling (L3544-3665) ----------------------------------------------------------------------------
  // SAMP_PA_RATE 1..65535, SAMP_PA_EDGE 0 rising / 1 falling / 2 none, SAMP_PA_LEVEL |v| <= 2^31-1,
  // SAMP_PA_TRIGCH 0..3, SAMP_PA_SRC_CHx = axis << 8 | source (ParametersInvalid; a source the card does not
  // sample: FunctionNotAvailable).
  AdlinkCode set_sampling_param(double para, double value);
  AdlinkCode sampling_param(double para, int& value) const;
  // Starts a block of `length` samples (1..1e6), `pretrigger` of them before the trigger (0..length-1; 0 when
  // there is no trigger), giving up after timeout_ms of card time (-1: one simulated hour, V83). A trigger on
  // a one-bit source: FunctionNotAvailable (trigger on the word, V80).
  AdlinkCode start_sampling(double length, double pretrigger, double timeout_ms);
  bool sampling_block_ready() const;      // the block is full
  long long sampling_ticks_left() const;  // servo ticks until the time-out, >= 0
  // The synchronous end: the full block copied into the buffer (NoError) or, none, the sampler stopped (TimeOut).
  AdlinkCode finish_sampling();
  // The asynchronous count: the samples copied into the buffer so far (the whole block once full; the
  // pre-trigger samples count once the trigger came); the sampler stops at the time-out.
  int sampling_count();
  void stop_sampling();
  // The run's DataArr (shared: the caller's array stays valid after the next run starts), null before a run.
  std::shared_ptr<std::vector<ApsSample>> sampling_buffer() const { return buffer_; }

  // -- position compare trigger (L3348-3435) and the compare timer (L3363-3378, AF15) ---------------------------
  // TGR_LCMPx_SRC / TGR_TCMPx_SRC (axis n, or 0x10 + n for its command position; V76), TGR_TCMPx_DIR 0..2,
  // TGR_TRG_EN (bit x: TRGx), TGR_TRGx_SRC (TRG_SRC_* bits 0..31), TGR_TRGx_PWD (x 100 ns, 1..1e7),
  // TGR_TRGx_LOGIC / TGR_TRGx_TGL 0..1; the timer TIMR_ITV (ticks 1..2^31-1), TIMR_DIR, TIMR_RING_EN, TIMR_EN
  // 0..1. A 4-axis card (PCI-8254) has TRG0-1 only. Applied to the card's position compare at once.
  AdlinkCode set_trigger_param(double para, double value);
  AdlinkCode trigger_param(double para, int& value) const;
  // The timer counter now: while TIMR_EN, +-1 every TIMR_ITV ticks (TIMR_DIR 0 up, 1 down), wrapping at 32 bits
  // with TIMR_RING_EN, else held at the I32 limits.
  std::int64_t timer_counter() const;
  AdlinkCode set_timer_counter(double value);

 private:
  double factor(const ApsSampleSource& s) const;
  int fill(const machine::SampleBlock& block);
  void apply_trigger();
  std::size_t trigger_outputs() const { return card_.axis_count() == 4 ? 2 : 4; }

  machine::Card& card_;
  static int slot(double para);        // index into samp_ of a sampling parameter number, -1 if none
  std::array<int, 8> samp_{};          // RATE, EDGE, LEVEL, TRIGCH, SRC_CH0..3
  std::array<std::int64_t, 0x24> tgr_{};  // trigger parameters 00h-1Fh and the timer 20h-23h
  std::int64_t timer_value_ = 0;
  long long timer_since_ = 0;
  // the sampling run
  bool running_ = false;
  std::array<std::size_t, 4> run_axis_{};
  std::array<const ApsSampleSource*, 4> run_src_{};
  std::size_t run_length_ = 0;
  long long run_until_ = 0;
  int run_done_ = -1;  // samples of the finished block, -1 while it fills
  std::shared_ptr<std::vector<ApsSample>> buffer_;
};

// The card's ADLINK scope module, created and attached on first use (owned by the card).
ApsScope& aps_scope(machine::Card& card);

}  // namespace servobench::vendor::adlink
