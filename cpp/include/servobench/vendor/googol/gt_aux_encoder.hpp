// GtAuxEncoders: the GT's two auxiliary encoder inputs, No. 1 and No. 2 (GT manual seed 000: GT_EncPos L3241-3265,
// GT_EncVel L3302-3330, GT_ClrEncPos L3124-3136, the sense bits 4-5 of GT_EncSns L595-635 / L3267-3300, the INDEX
// capture of encoder 1: GT_SetEncCapt L4733-4747, GT_GetEncSts L3743-3759, GT_GetEncCapt L3727-3741; decision GT8,
// GZ1-GZ5): the card's registers (the zero offsets, the capture state) and all the arithmetic over the counts.
//
// The encoders themselves are the machine's (servobench.card_io.AuxEncoder: a constant or a Python function of the
// card time); the card reads them through AuxInputs::counts, the raw whole count of encoder n (0, 1) at card time
// t_s (s), 0 when nothing is connected -- the one thing the host evaluates. Units: pulse (counts), pulse/ST (ST =
// the card's servo tick); t = tick x servo period (s).
//
//   sign_n      = -1 if the wiring's reversed bit 4+n XOR EncSns bit 4+n, else +1
//   position_n  = sign_n raw_n(t) - zero_n                                          (GT_EncPos, pulse)
//   velocity_n  = position_n(t) - position_n(max(0, t - ST))                        (GT_EncVel, pulse/ST)
//   GT_ClrEncPos: zero_n += position_n(t)                                           (the read becomes 0)
//   GT_EncSns:    zero_n += (sign_new - sign_old) raw_n(t)                          (the read stays where it is)
//   index mark from count a to count b (marks at off + k N, N = counts per index; the first in the direction
//   of travel):  b > a: k = floor((a - off) / N) + 1, reached when off + k N <= b;
//                b < a: k = ceil((a - off) / N) - 1,  reached when off + k N >= b;  the count is floor(off + k N)
//   capture:     GT_SetEncCapt arms at raw_0(t_arm); each status/value read scans the ticks since the last scan,
//                k = last + 1 .. tick, raw_0(k ST); the first mark between consecutive counts latches
//                captured = sign_0 mark - zero_0 (GT_GetEncSts bit 3) and disarms; GT_GetEncCapt reads the last
//                captured value (0 before any) while nothing new is captured.
#pragma once

#include <array>
#include <functional>
#include <optional>

namespace servobench::machine {
class Card;
}

namespace servobench::vendor::googol {

// What the machine gives the auxiliary-encoder inputs at one read (servobench.card_io's wiring).
struct AuxInputs {
  // raw whole count (pulse) of encoder n (0 = No. 1, 1 = No. 2) at card time t_s (s); 0 when nothing is connected.
  std::function<long long(int n, double t_s)> counts;
  int reversed = 0;                // the wiring (card_io encoder_reversed): bits 0-3 axes 1-4, bits 4, 5 encoder
                                   // 1, 2; 1 = counts against the motor
  long long counts_per_index = 0;  // encoder 1: counts between two index marks, 0 = no mark
  double index_offset = 0.0;       // encoder 1: the position of one index mark, pulse
};

// The first index-mark count reached moving from count a to count b (marks at index_offset + k counts_per_index),
// or none (a == b, counts_per_index == 0). counts_per_index must be >= 0 (std::invalid_argument otherwise).
std::optional<long long> index_mark_between(long long a, long long b, long long counts_per_index,
                                            double index_offset);

// The capture registers of encoder 1 (GT_SetEncCapt).
struct AuxCapture {
  bool set = false;       // GT_SetEncCapt ran at least once
  bool armed = false;
  bool captured = false;  // GT_GetEncSts bit 3
  long long tick = 0;     // the last tick the scan looked at
  long long raw = 0;      // encoder 1's raw count at that tick, pulse
  long long value = 0;    // GT_GetEncCapt: the captured position, pulse
};

// The registers and arithmetic; n is the encoder, 0 (No. 1) or 1 (No. 2), already checked by the GT command
// (GtCard::enc_pos ...), and enc_sns GT_EncSns' word (bits 4-5 used).
class GtAuxEncoders {
 public:
  explicit GtAuxEncoders(const machine::Card& card) : card_(card) {}

  // position_n now, pulse (GT_EncPos).
  long long position(int n, int enc_sns, const AuxInputs& in) const;
  // velocity_n now, pulse/ST (GT_EncVel).
  double velocity(int n, int enc_sns, const AuxInputs& in) const;
  // The position of encoder n becomes 0 (GT_ClrEncPos).
  void clear(int n, int enc_sns, const AuxInputs& in);
  // The zero offsets such that each read stays where it is when the sense bits 4-5 change (GT_EncSns).
  void keep_position_on_sense(int old_sns, int new_sns, const AuxInputs& in);
  // Arms the INDEX capture of encoder 1 and clears its captured flag (GT_SetEncCapt).
  void arm_capture(const AuxInputs& in);
  // Scans the ticks since the last scan for encoder 1's index mark (see the header comment); the registers after.
  const AuxCapture& scan(int enc_sns, const AuxInputs& in);

  const std::array<long long, 2>& zero() const { return zero_; }
  const AuxCapture& capture() const { return capt_; }

 private:
  double now_s() const;
  static long long raw(int n, double t_s, const AuxInputs& in);
  static int sign(int n, int enc_sns, const AuxInputs& in);
  long long value_at(int n, double t_s, int enc_sns, const AuxInputs& in) const;

  const machine::Card& card_;
  std::array<long long, 2> zero_{};  // GT_ClrEncPos / GT_EncSns: the zero of each encoder, pulse
  AuxCapture capt_{};
};

}  // namespace servobench::vendor::googol
