#include "servobench/plant/lti.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "servobench/common/validate.hpp"

namespace servobench::plant {

namespace {

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("LtiPlant." + what); }

double rel_tol(double scale) { return 1e-9 * (scale > 0 ? scale : 1.0); }

// The rows [C; C A] of the change of coordinates and an orthonormal basis of their complement.
Eigen::MatrixXd transform(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c) {
  const Eigen::Index n = a.rows();
  Eigen::MatrixXd top(2, n);
  top.row(0) = c;
  top.row(1) = c * a;
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(top.transpose());
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd t(n, n);
  t.topRows(2) = top;
  if (n > 2) t.bottomRows(n - 2) = q.rightCols(n - 2).transpose();
  return t;
}

}  // namespace

LtiPlantParams::LtiPlantParams() {
  const double j = 1e-4, visc = 1e-4;
  a = Eigen::MatrixXd::Zero(2, 2);
  a(0, 1) = 1.0;
  a(1, 1) = -visc / j;
  b = Eigen::MatrixXd::Zero(2, 1);
  b(1, 0) = 1.0 / j;
  c = Eigen::MatrixXd::Zero(1, 2);
  c(0, 0) = 1.0;
}

void LtiPlantParams::port_model(Eigen::MatrixXd& a_out, Eigen::MatrixXd& b_out, Eigen::MatrixXd& c_out) const {
  const double k = lead_m_per_rev > 0 ? 2.0 * M_PI / lead_m_per_rev : 1.0;
  a_out = a;
  b_out = b * k;
  c_out = c * k;
}

void LtiPlantParams::validate() const {
  const Eigen::Index n = a.rows();
  if (n < 2 || n > kMaxLtiStates)
    bad("a: " + std::to_string(n) + " states; an LtiPlant has 2.." + std::to_string(kMaxLtiStates) +
        " (relative degree >= 2 needs 2; the power train holds " + std::to_string(kMaxLtiStates) +
        " plant states next to the current loop, decision LT2)");
  if (a.cols() != n) bad("a must be square, got " + std::to_string(n) + " x " + std::to_string(a.cols()));
  if (b.rows() != n || b.cols() != 1)
    bad("b must be " + std::to_string(n) + " x 1 (one input: the torque), got " + std::to_string(b.rows()) + " x " +
        std::to_string(b.cols()));
  if (c.rows() != 1 || c.cols() != n)
    bad("c must be 1 x " + std::to_string(n) + " (one output: the encoder angle), got " + std::to_string(c.rows()) +
        " x " + std::to_string(c.cols()));
  for (const Eigen::MatrixXd* m : {&a, &b, &c}) {
    const char* name = m == &a ? "a" : (m == &b ? "b" : "c");
    for (Eigen::Index i = 0; i < m->size(); ++i) {
      const double v = m->data()[i];
      if (!std::isfinite(v) || std::fabs(v) > kMaxMagnitude)
        throw_invalid("LtiPlant", name, v, "is not a finite number within +-" + format_value(kMaxMagnitude));
    }
  }
  if (d != 0.0)
    throw_invalid("LtiPlant", "d", d, "must be 0: a torque cannot move the angle at once (decision LT1)");
  check_nonnegative("LtiPlant", "lead_m_per_rev", lead_m_per_rev);
  if (c.norm() == 0.0) bad("c is zero: the encoder reads no state");
  if (b.norm() == 0.0) bad("b is zero: the torque drives no state");
  const double cb = (c * b)(0, 0);
  if (std::fabs(cb) > rel_tol(c.norm() * b.norm()))
    throw_invalid("LtiPlant", "c @ b", cb,
                  "must be 0: the relative degree from torque to angle must be >= 2 (a torque accelerates; the "
                  "angle is the integral of a speed; decision LT1)");
  Eigen::MatrixXd top(2, n);
  top.row(0) = c.normalized();
  top.row(1) = c * a;
  if (top.row(1).norm() > 0) top.row(1).normalize();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(top);
  if (!(svd.singularValues()(1) > 1e-9))
    bad("a: c @ a is parallel to c, so the angle never responds to the torque (the output is decoupled from b)");
  friction().validate("LtiPlant", "");
  check_range("LtiPlant", "load_nm", load_nm, -1e6, 1e6);
  if (friction().has_dry_friction() && !(inertia_kgm2() > 0))
    throw_invalid("LtiPlant", "coulomb_nm", coulomb_nm,
                  "needs a plant of relative degree 2 with c @ a @ b > 0 (a finite inertia 1/(c a b) at the motor for "
                  "the friction to act on); this model has c @ a @ b = " +
                      format_value((c * a * b)(0, 0)));
}

double LtiPlantParams::inertia_kgm2() const {
  Eigen::MatrixXd ap, bp, cp;
  port_model(ap, bp, cp);
  const double cab = (cp * ap * bp)(0, 0);
  const double scale = cp.norm() * ap.norm() * bp.norm();
  return cab > rel_tol(scale) ? 1.0 / cab : 0.0;
}

std::string LtiPlantParams::stability() const {
  const Eigen::VectorXcd p = a.eigenvalues();
  // A multiple pole at 0 (the free integrators of a drive train) comes out of the eigenvalue solver split by about
  // sqrt(eps |A|) (6e-5 1/s on a two-mass train with |A| = 2e7): 1e-6 of the largest |pole| absorbs that.
  const double tol = std::max(1e-12, 1e-6 * p.cwiseAbs().maxCoeff());
  int rhp = 0, axis = 0;
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    if (p(i).real() > tol) ++rhp;
    else if (p(i).real() >= -tol) ++axis;
  }
  if (rhp > 0) return "unstable (" + std::to_string(rhp) + " poles in Re s > 0)";
  if (axis > 0) return "marginal (" + std::to_string(axis) + " poles on the imaginary axis)";
  return "stable";
}

Mechanics lti_mechanics(const LtiPlantParams& p) {
  p.validate();
  Eigen::MatrixXd a, b, c;
  p.port_model(a, b, c);
  const Eigen::Index n = a.rows();
  const Eigen::MatrixXd t = transform(a, c);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(t);
  const Eigen::MatrixXd az = t * a * lu.inverse();
  Eigen::VectorXd bz = t * b;
  Mechanics m;
  m.a = az;
  // z0' = z1 and z0 is not driven by the torque: exact, not up to rounding.
  m.a.row(0).setZero();
  m.a(0, 1) = 1.0;
  bz(0) = 0.0;
  m.b.resize(n, 3);
  for (int k = 0; k < 3; ++k) m.b.col(k) = bz;  // motor torque, friction and disturbances all act at the input
  Body body;
  body.angle_index = 0;
  body.speed_index = 1;
  body.torque_input = 1;
  body.inertia_kgm2 = p.inertia_kgm2();
  body.friction = p.friction();
  m.bodies = {body};
  m.disturbances = Disturbances{p.load_nm, 0.0, 0.0, 0.0};
  m.motor_angle = m.load_angle = 0;
  m.motor_speed = m.load_speed = 1;
  // Rest at angle 1 rad: A z = 0 with z0 = 1, from the null space of A (the free integrator).
  const Eigen::FullPivLU<Eigen::MatrixXd> alu(m.a);
  m.rest = Eigen::VectorXd::Zero(n);
  m.rest(0) = 1.0;
  m.rest_anywhere = false;
  const Eigen::MatrixXd ker = alu.kernel();
  if (alu.rank() < n) {
    Eigen::Index best = 0;
    for (Eigen::Index k = 1; k < ker.cols(); ++k)
      if (std::fabs(ker(0, k)) > std::fabs(ker(0, best))) best = k;
    if (std::fabs(ker(0, best)) > 1e-9 * ker.col(best).norm()) {
      m.rest = ker.col(best) / ker(0, best);
      m.rest(1) = 0.0;  // z1 = z0' = 0 at rest exactly
      m.rest_anywhere = true;
    }
  }
  return m;
}

}  // namespace servobench::plant
