// LtiPlant (plant/lti.hpp): validation, the change of coordinates (angle and speed as states), the same power
// train as a rigid plant given as matrices, the rest direction.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "servobench/machine/powertrain.hpp"
#include "servobench/plant/lti.hpp"
#include "servobench/plant/rigid.hpp"

using namespace servobench;

namespace {
plant::LtiPlantParams third_order() {  // 1/(s+1)^3 in controllable form, output the last state
  plant::LtiPlantParams p;
  p.a = Eigen::MatrixXd::Zero(3, 3);
  p.a << -3, -3, -1, 1, 0, 0, 0, 1, 0;
  p.b = Eigen::MatrixXd::Zero(3, 1);
  p.b(0, 0) = 1;
  p.c = Eigen::MatrixXd::Zero(1, 3);
  p.c(0, 2) = 1;
  return p;
}
}  // namespace

TEST(LtiPlant, ValidatesShapeAndRelativeDegree) {
  plant::LtiPlantParams p = third_order();
  EXPECT_NO_THROW(p.validate());
  EXPECT_EQ(p.stability(), "stable");
  EXPECT_EQ(p.inertia_kgm2(), 0.0);  // relative degree 3
  plant::LtiPlantParams q = p;
  q.d = 1;
  EXPECT_THROW(q.validate(), std::invalid_argument);
  q = p;
  q.c(0, 0) = 1;  // c b != 0
  EXPECT_THROW(q.validate(), std::invalid_argument);
  q = p;
  q.coulomb_nm = 0.1;  // friction needs relative degree 2
  EXPECT_THROW(q.validate(), std::invalid_argument);
  q = p;
  q.a(0, 0) = std::nan("");
  EXPECT_THROW(q.validate(), std::invalid_argument);
  q.a = Eigen::MatrixXd::Zero(8, 8);
  EXPECT_THROW(q.validate(), std::invalid_argument);
}

TEST(LtiPlant, AngleAndSpeedAreTheFirstStates) {
  const plant::Mechanics m = plant::lti_mechanics(third_order());
  EXPECT_EQ(m.a(0, 1), 1.0);
  EXPECT_EQ(m.a(0, 0), 0.0);
  EXPECT_EQ(m.b(0, 0), 0.0);
  EXPECT_FALSE(m.rest_anywhere);  // no integrator
  // the same frequency response as the model: 1/(j w + 1)^3
  const auto h = plant::frequency_response(m, {0.1, 0.5}, false, 0.0);
  for (int k = 0; k < 2; ++k) {
    const std::complex<double> s(0.0, 2 * M_PI * (k == 0 ? 0.1 : 0.5));
    EXPECT_NEAR(std::abs(h[k] - 1.0 / ((s + 1.0) * (s + 1.0) * (s + 1.0))), 0.0, 1e-12);
  }
}

TEST(LtiPlant, RigidBodyAsMatricesSteppsLikeRigidPlant) {
  plant::RigidPlantParams r;
  r.inertia_kgm2 = 2e-4;
  r.viscous_nms = 3e-4;
  r.coulomb_nm = 0.01;
  plant::LtiPlantParams l;
  l.a = Eigen::MatrixXd::Zero(2, 2);
  l.a(0, 1) = 1;
  l.a(1, 1) = -r.viscous_nms / r.inertia_kgm2;
  l.b = Eigen::MatrixXd::Zero(2, 1);
  l.b(1, 0) = 1 / r.inertia_kgm2;
  l.c = Eigen::MatrixXd::Zero(1, 2);
  l.c(0, 0) = 1;
  l.coulomb_nm = r.coulomb_nm;
  EXPECT_NEAR(l.inertia_kgm2(), 2e-4, 1e-16);
  drive::TorqueDriveParams d;
  machine::PowerTrain a(d, plant::rigid_mechanics(r), 200e-6, 2), b(d, plant::lti_mechanics(l), 200e-6, 2);
  for (int k = 0; k < 2000; ++k) {
    const double v = 2.0 * std::sin(k * 0.01);
    a.set_input(v);
    b.set_input(v);
    a.advance_tick();
    b.advance_tick();
    ASSERT_NEAR(a.motor_angle_rad(), b.motor_angle_rad(), 1e-12) << k;
    ASSERT_NEAR(a.motor_speed_rad_s(), b.motor_speed_rad_s(), 1e-9) << k;
  }
  b.reset(1.5);  // a free integrator: rest anywhere
  b.set_input(0.0);
  b.advance_tick();
  EXPECT_EQ(b.motor_angle_rad(), 1.5);
  machine::PowerTrain c(d, plant::lti_mechanics(third_order()), 200e-6, 1);
  EXPECT_THROW(c.reset(1.0), std::invalid_argument);
}
