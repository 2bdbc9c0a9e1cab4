#include "servobench/tuning/spectral_lines.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"
#include "vector_clones.hpp"

namespace servobench::tuning {

namespace {
constexpr const char* kOwner = "h1_estimate";
constexpr double kPi = 3.141592653589793;
using Complex = std::complex<double>;

struct Twiddles {
  std::vector<double> c, s;  // cos, sin of 2 pi m / n
  explicit Twiddles(int n) : c(n), s(n) {
    for (int m = 0; m < n; ++m) {
      c[m] = std::cos(2 * kPi * m / n);
      s[m] = std::sin(2 * kPi * m / n);
    }
  }
};

void check_lines(const std::vector<int>& lines, int n) {
  for (int k : lines)
    if (k < 0 || k >= n) throw_invalid(kOwner, "lines", k, "must lie in 0.." + std::to_string(n - 1));
}
}  // namespace

namespace {
// DFTs of M signals of n samples at the lines, all at once: out[m * L + i] = X_m(lines[i]). The twiddle of each line
// runs as a phasor z <- z w, w = exp(-2 pi j k / n), re-anchored on the exact table value every kBlock samples (the
// rotation's rounding stays below 1e-13); lines are the inner, unit-stride loop (vectorised), taken 64 at a time so
// that their sums stay in the L1 cache while the signals stream past.
SERVOBENCH_VECTOR_CLONES
std::vector<Complex> dft_lines_many(const std::vector<const double*>& x, int n, const std::vector<int>& lines,
                                    const Twiddles& tw) {
  constexpr int kBlock = 256;        // samples between re-anchorings of the phasors
  constexpr std::size_t kTile = 64;  // lines per pass over the data: their sums stay in the L1 cache
  const std::size_t L = lines.size(), M = x.size();
  std::vector<double> wr(L), wi(L), zr(L), zi(L), ar(M * L, 0.0), ai(M * L, 0.0);
  for (std::size_t l = 0; l < L; ++l) {
    wr[l] = tw.c[lines[l]];
    wi[l] = -tw.s[lines[l]];
  }
  for (std::size_t l0 = 0; l0 < L; l0 += kTile) {
    const std::size_t l1 = std::min(L, l0 + kTile);
    for (int j0 = 0; j0 < n; j0 += kBlock) {
      const int j1 = std::min(n, j0 + kBlock);
      for (std::size_t l = l0; l < l1; ++l) {
        const long long idx = (static_cast<long long>(lines[l]) * j0) % n;
        zr[l] = tw.c[idx];
        zi[l] = -tw.s[idx];
      }
      for (int j = j0; j < j1; ++j) {
        for (std::size_t m = 0; m < M; ++m) {
          const double v = x[m][j];
          double* __restrict pr = ar.data() + m * L;
          double* __restrict pi = ai.data() + m * L;
          const double* __restrict cr = zr.data();
          const double* __restrict ci = zi.data();
          for (std::size_t l = l0; l < l1; ++l) {
            pr[l] += v * cr[l];
            pi[l] += v * ci[l];
          }
        }
        double* __restrict cr = zr.data();
        double* __restrict ci = zi.data();
        const double* __restrict rr = wr.data();
        const double* __restrict ri = wi.data();
        for (std::size_t l = l0; l < l1; ++l) {
          const double re = cr[l] * rr[l] - ci[l] * ri[l];
          ci[l] = cr[l] * ri[l] + ci[l] * rr[l];
          cr[l] = re;
        }
      }
    }
  }
  std::vector<Complex> out(M * L);
  for (std::size_t i = 0; i < M * L; ++i) out[i] = Complex(ar[i], ai[i]);
  return out;
}
}  // namespace

std::vector<Complex> dft_lines(const double* x, int n, const std::vector<int>& lines) {
  if (n < 1) throw_invalid("dft_lines", "n", n, "must be >= 1");
  check_lines(lines, n);
  return dft_lines_many({x}, n, lines, Twiddles(n));
}

H1Estimate h1_estimate(const std::vector<double>& r, const std::vector<double>& e, const std::vector<double>& u,
                       const std::vector<double>& y, int record_ticks, int records, int skip_ticks,
                       const std::vector<int>& lines, double servo_period_s, bool remove_offset) {
  const int n = record_ticks;
  if (n < 1) throw_invalid(kOwner, "record_ticks", n, "must be >= 1");
  if (records < 1) throw_invalid(kOwner, "records", records, "must be >= 1");
  if (skip_ticks < 0) throw_invalid(kOwner, "skip_ticks", skip_ticks, "must be >= 0");
  check_positive(kOwner, "servo_period_s", servo_period_s, 1.0);
  check_lines(lines, n);
  const std::size_t need = static_cast<std::size_t>(skip_ticks) + static_cast<std::size_t>(records) * n;
  const std::vector<double>* sig[4] = {&r, &e, &u, &y};
  for (const auto* s : sig)
    if (s->size() != need)
      throw_invalid(kOwner, "signals", static_cast<double>(s->size()),
                    "must each hold skip_ticks + records * record_ticks = " + std::to_string(need) + " samples");
  const Twiddles tw(n);
  // Records with their offsets (each record's first sample) removed when asked.
  std::vector<double> data[4];
  for (int q = 0; q < 4; ++q) {
    data[q].assign(sig[q]->begin() + skip_ticks, sig[q]->end());
    if (remove_offset)
      for (int rec = 0; rec < records; ++rec) {
        double* p = data[q].data() + static_cast<std::size_t>(rec) * n;
        const double off = p[0];
        for (int j = 0; j < n; ++j) p[j] -= off;
      }
  }
  auto record = [&](int q, int rec) { return data[q].data() + static_cast<std::size_t>(rec) * n; };
  // A periodic reference (every record of R the same, as the tiled multisine and chirp records): its spectrum is
  // computed once and the cross spectra are conj(R) times the spectra of the summed records (DFTs are linear).
  bool periodic = true;
  for (int rec = 1; rec < records && periodic; ++rec)
    periodic = std::equal(record(0, rec), record(0, rec) + n, record(0, 0));
  const std::size_t m = lines.size();
  std::vector<double> sum_e, sum_u;
  std::vector<const double*> x;
  if (periodic) {
    sum_e.assign(record(1, 0), record(1, 0) + n);
    sum_u.assign(record(2, 0), record(2, 0) + n);
    for (int rec = 1; rec < records; ++rec)
      for (int j = 0; j < n; ++j) {
        sum_e[j] += record(1, rec)[j];
        sum_u[j] += record(2, rec)[j];
      }
    x = {record(0, 0), sum_e.data(), sum_u.data()};
    for (int rec = 0; rec < records; ++rec) x.push_back(record(3, rec));
  } else {
    for (int rec = 0; rec < records; ++rec)
      for (int q = 0; q < 4; ++q) x.push_back(record(q, rec));
  }
  const std::vector<Complex> X = dft_lines_many(x, n, lines, tw);
  auto at = [&](std::size_t signal, std::size_t i) { return X[signal * m + i]; };
  H1Estimate out;
  out.freq_hz.resize(m);
  out.plant.resize(m);
  out.open_loop.resize(m);
  out.closed_loop.resize(m);
  out.coherence.resize(m);
  const double df = 1.0 / (n * servo_period_s);
  for (std::size_t i = 0; i < m; ++i) {
    Complex s_ry, s_re, s_ru;
    double s_rr = 0, s_yy = 0;
    if (periodic) {
      const Complex R = at(0, i);
      Complex sum_y;
      for (int rec = 0; rec < records; ++rec) {
        const Complex Y = at(3 + rec, i);
        sum_y += Y;
        s_yy += std::norm(Y);
      }
      s_ry = std::conj(R) * sum_y;
      s_re = std::conj(R) * at(1, i);
      s_ru = std::conj(R) * at(2, i);
      s_rr = records * std::norm(R);
    } else {
      for (int rec = 0; rec < records; ++rec) {
        const Complex R = at(4 * rec, i), E = at(4 * rec + 1, i), U = at(4 * rec + 2, i), Y = at(4 * rec + 3, i);
        s_ry += std::conj(R) * Y;
        s_re += std::conj(R) * E;
        s_ru += std::conj(R) * U;
        s_rr += std::norm(R);
        s_yy += std::norm(Y);
      }
    }
    out.freq_hz[i] = static_cast<double>(lines[i]) * df;
    out.plant[i] = s_ry / s_ru;
    out.open_loop[i] = s_ry / s_re;
    out.closed_loop[i] = s_ry / s_rr;
    const double coh = records > 1 ? std::norm(s_ry) / (s_rr * s_yy) : 1.0;
    out.coherence[i] = std::clamp(coh, 0.0, 1.0);
  }
  return out;
}

}  // namespace servobench::tuning
