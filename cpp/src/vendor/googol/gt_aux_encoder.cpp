// GtAuxEncoders: the GT auxiliary encoders' registers and arithmetic (vendor/googol/gt_aux_encoder.hpp).
#include "servobench/vendor/googol/gt_aux_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/machine/card.hpp"

namespace servobench::vendor::googol {

std::optional<long long> index_mark_between(long long a, long long b, long long counts_per_index,
                                            double index_offset) {
  if (counts_per_index < 0)
    throw std::invalid_argument("counts_per_index = " + std::to_string(counts_per_index) +
                                " must be >= 0 (0 = no index mark)");
  const long long n = counts_per_index;
  if (n == 0 || a == b) return std::nullopt;
  const double off = index_offset;
  const double q = (static_cast<double>(a) - off) / static_cast<double>(n);
  const long long k = b > a ? static_cast<long long>(std::floor(q)) + 1 : static_cast<long long>(std::ceil(q)) - 1;
  const double mark = off + static_cast<double>(k * n);
  if (b > a ? mark <= static_cast<double>(b) : mark >= static_cast<double>(b))
    return static_cast<long long>(std::floor(mark));
  return std::nullopt;
}

double GtAuxEncoders::now_s() const {
  return static_cast<double>(card_.tick()) * card_.servo_period_s();
}

long long GtAuxEncoders::raw(int n, double t_s, const AuxInputs& in) {
  return in.counts ? in.counts(n, t_s) : 0;
}

int GtAuxEncoders::sign(int n, int enc_sns, const AuxInputs& in) {
  return ((in.reversed ^ enc_sns) >> (4 + n)) & 1 ? -1 : 1;
}

long long GtAuxEncoders::value_at(int n, double t_s, int enc_sns, const AuxInputs& in) const {
  return sign(n, enc_sns, in) * raw(n, t_s, in) - zero_[n];
}

long long GtAuxEncoders::position(int n, int enc_sns, const AuxInputs& in) const {
  return value_at(n, now_s(), enc_sns, in);
}

double GtAuxEncoders::velocity(int n, int enc_sns, const AuxInputs& in) const {
  const double t = now_s();
  const double before = std::max(0.0, t - card_.servo_period_s());
  return static_cast<double>(value_at(n, t, enc_sns, in) - value_at(n, before, enc_sns, in));
}

void GtAuxEncoders::clear(int n, int enc_sns, const AuxInputs& in) { zero_[n] += position(n, enc_sns, in); }

void GtAuxEncoders::keep_position_on_sense(int old_sns, int new_sns, const AuxInputs& in) {
  const double t = now_s();
  for (int n = 0; n < 2; ++n) {
    const int d = sign(n, new_sns, in) - sign(n, old_sns, in);
    if (d != 0) zero_[n] += d * raw(n, t, in);
  }
}

void GtAuxEncoders::arm_capture(const AuxInputs& in) {
  capt_.set = capt_.armed = true;
  capt_.captured = false;
  capt_.tick = card_.tick();
  capt_.raw = raw(0, now_s(), in);
}

const AuxCapture& GtAuxEncoders::scan(int enc_sns, const AuxInputs& in) {
  if (!capt_.armed) return capt_;
  const long long now = card_.tick();
  const double ts = card_.servo_period_s();
  for (long long k = capt_.tick + 1; k <= now; ++k) {
    const long long r = raw(0, static_cast<double>(k) * ts, in);
    const auto mark = index_mark_between(capt_.raw, r, in.counts_per_index, in.index_offset);
    capt_.raw = r;
    capt_.tick = k;
    if (mark) {
      capt_.armed = false;
      capt_.captured = true;
      capt_.value = sign(0, enc_sns, in) * *mark - zero_[0];
      break;
    }
  }
  capt_.tick = std::max(capt_.tick, now);
  return capt_;
}

}  // namespace servobench::vendor::googol
