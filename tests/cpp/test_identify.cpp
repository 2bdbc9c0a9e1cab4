// Identification layer: the discretisation's derivatives, the model against the simulator, a rigid fit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "servobench/identify/plant_model.hpp"
#include "servobench/identify/time_fit.hpp"
#include "servobench/machine/powertrain.hpp"
#include "servobench/plant/zoh.hpp"

using namespace servobench;

TEST(Identify, VanLoanDerivativesMatchFiniteDifferences) {
  // d/dp of the two-mass ZOH (with a current loop) against central differences of the plain ZOH.
  identify::ModelLayout layout;
  layout.model = identify::PlantModel::kTwoMass;
  layout.current_bw_hz = 1500.0;
  const std::vector<double> p = {1e-4, 2e-4, 300.0, 0.01, 2e-4, 1e-5};
  const double h = 200e-6;
  const identify::Discretisation d = identify::discretise(layout, p, h, true);
  for (std::size_t k = 0; k < p.size(); ++k) {
    std::vector<double> hi = p, lo = p;
    const double step = 1e-4 * p[k];
    hi[k] += step;
    lo[k] -= step;
    const auto dh = identify::discretise(layout, hi, h, false), dl = identify::discretise(layout, lo, h, false);
    for (std::size_t mask = 0; mask < d.phi.size(); ++mask) {
      const Eigen::MatrixXd fd_phi = (dh.phi[mask] - dl.phi[mask]) / (2 * step);
      const Eigen::MatrixXd fd_gamma = (dh.gamma[mask] - dl.gamma[mask]) / (2 * step);
      EXPECT_LE((fd_phi - d.dphi[mask][k]).norm(), 1e-5 * (1.0 + d.dphi[mask][k].norm())) << "k " << k << " mask " << mask;
      EXPECT_LE((fd_gamma - d.dgamma[mask][k]).norm(), 1e-5 * (1.0 + d.dgamma[mask][k].norm())) << "k " << k;
    }
  }
}

TEST(Identify, ModelIsTheSimulatorsPowerTrain) {
  // Open-loop torque steps through a rigid plant with Coulomb and Stribeck friction: the identification model
  // (on double) and machine::PowerTrain give the same angles (same matrices, same ZOH, same friction sub-step).
  plant::RigidPlantParams rp;
  rp.inertia_kgm2 = 2e-4;
  rp.viscous_nms = 3e-4;
  rp.coulomb_nm = 0.03;
  rp.static_nm = 0.05;
  rp.stribeck_speed_rad_s = 2.0;
  drive::TorqueDriveParams dp;
  dp.amps_per_volt = 1.0;
  dp.kt = 1.0;
  dp.current_limit_a = drive::kInf;
  dp.current_bw_hz = 1500.0;
  const double ts = 200e-6;
  machine::PowerTrain pt(dp, plant::rigid_mechanics(rp), ts, 1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.12, 0.12);
  identify::TimeLog log;
  log.sample_period_s = ts;
  std::vector<double> angle;
  double level = 0.0;
  for (int k = 0; k < 5000; ++k) {
    if (k % 400 == 0) level = k == 0 ? 0.0 : u(rng);  // from rest with no current, as the model assumes i(0) = u(0)
    log.torque_nm.push_back(level);
    angle.push_back(pt.motor_angle_rad());
    pt.set_input(level);
    pt.advance_tick();
  }
  identify::TimeFitOptions o;
  o.current_bw_hz = 1500.0;
  const std::vector<double> p = {2e-4, 3e-4, 0.03, 0.05, 2.0, 0.0};
  // The log's torque k is held over [t_k, t_k+1), as PowerTrain's input set before tick k.
  const std::vector<double> sim2 = identify::simulate_model(log, p, {0.0, 0.0}, o);
  double worst2 = 0.0;
  for (std::size_t k = 0; k < angle.size(); ++k) worst2 = std::max(worst2, std::fabs(sim2[k] - angle[k]));
  EXPECT_LE(worst2, 1e-12);
}

namespace {

// A still log of 100 samples at 5 kHz (measured: `measured` samples) and a rigid start.
identify::TimeLog still_log(std::size_t measured) {
  identify::TimeLog log;
  log.sample_period_s = 200e-6;
  log.torque_nm.assign(100, 0.0);
  log.measured.assign(measured, 0.0);
  return log;
}
identify::ParameterSetup rigid_start() {
  identify::ParameterSetup s;
  s.initial = {1e-4, 0, 0, 0, 1, 0};
  return s;
}

}  // namespace

TEST(Identify, RefusesBadLogs) {
  identify::TimeLog log = still_log(99);
  const identify::ParameterSetup s = rigid_start();
  EXPECT_THROW(identify::fit_time_domain(log, s, {}), std::invalid_argument);
  log.measured.assign(100, 0.0);
  log.measured[5] = std::nan("");
  EXPECT_THROW(identify::fit_time_domain(log, s, {}), std::invalid_argument);
}

// StageJoin's tolerance (decision FV15) must be in (0, 1): the error names the struct and the field, before the log is
// read (this log is valid).
TEST(Identify, RefusesAStageJoinToleranceOutsideZeroToOne) {
  const identify::TimeLog log = still_log(100);
  const identify::ParameterSetup s = rigid_start();
  for (double rtol : {0.0, -1e-4, 1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    identify::StageJoin join;
    join.rtol = rtol;
    try {
      identify::fit_time_domain(log, s, {}, &join);
      ADD_FAILURE() << "rtol " << rtol << " accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("StageJoin"), std::string::npos) << what;
      EXPECT_NE(what.find("rtol"), std::string::npos) << what;
      EXPECT_NE(what.find("(0, 1)"), std::string::npos) << what;
    }
  }
}
