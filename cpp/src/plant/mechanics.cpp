#include "servobench/plant/mechanics.hpp"

#include <Eigen/Dense>

#include "servobench/common/validate.hpp"
#include "servobench/plant/zoh.hpp"

namespace servobench::plant {

std::vector<std::complex<double>> frequency_response(const Mechanics& m, const std::vector<double>& freq_hz,
                                                     bool load_side, double period_s) {
  using C = std::complex<double>;
  const Eigen::Index n = m.a.rows();
  Eigen::MatrixXcd a;
  Eigen::VectorXcd b;
  if (period_s > 0) {
    const Zoh z = discretize_zoh(m.a, m.b.col(0), period_s);
    a = z.phi.cast<C>();
    b = z.gamma.col(0).cast<C>();
  } else {
    a = m.a.cast<C>();
    b = m.b.col(0).cast<C>();
  }
  const int out = load_side ? m.load_angle : m.motor_angle;
  std::vector<C> h(freq_hz.size());
  for (std::size_t k = 0; k < freq_hz.size(); ++k) {
    const double f = freq_hz[k];
    if (!(f > 0) || !std::isfinite(f)) throw_invalid("frequency_response", "freq_hz", f, "must be finite and > 0");
    if (period_s > 0 && f >= 0.5 / period_s)
      throw_invalid("frequency_response", "freq_hz", f,
                    "must be below the Nyquist frequency " + format_value(0.5 / period_s) + " Hz");
    const double w = 2.0 * M_PI * f;
    const C s = period_s > 0 ? std::exp(C(0.0, w * period_s)) : C(0.0, w);
    const Eigen::MatrixXcd m_s = s * Eigen::MatrixXcd::Identity(n, n) - a;
    const Eigen::VectorXcd x = m_s.partialPivLu().solve(b);
    h[k] = x(out);
  }
  return h;
}

}  // namespace servobench::plant
