// Shared fixtures of the card tests: the tuned demo axis (GT law Kp 38, Ki 60, Kd 830, Kaff 12870 on a rigid
// 1e-4 kg*m^2 plant, as servobench.demo_axis; servo period in s), the ADLINK test axis (the same gains in the APS
// law's scaling, Kp 38 x 1024, Kd 830 x 32, at the ADLINK servo period 250 us, L1733) and a staged T-curve move
// committed by Update.
#pragma once

#include <cstddef>

#include "servobench/machine/card.hpp"

namespace servobench::test {

inline machine::AxisConfig tuned_axis(double period_s = 200e-6) {
  machine::AxisConfig cfg;
  control::GtServoLawParams law;
  law.kp = 38;
  law.ki = 60;
  law.kd = 830;
  law.kaff = 12870;
  cfg.law = law;
  plant::RigidPlantParams plant;
  plant.inertia_kgm2 = 1e-4;
  plant.viscous_nms = 1e-4;
  cfg.plant = plant;
  cfg.servo_period_s = period_s;
  return cfg;
}

// The ADLINK test axis of the ADLINK tests (test_aps_*.cpp, test_card_adlink.cpp, test_vendor_modules.cpp).
inline machine::AxisConfig aps_axis() {
  machine::AxisConfig cfg;
  control::ApsServoLawParams law;
  law.kp = 38 * 1024;
  law.kd = 830 * 32;
  cfg.law = law;
  cfg.servo_period_s = 250e-6;
  plant::RigidPlantParams plant;
  plant.inertia_kgm2 = 1e-4;
  plant.viscous_nms = 1e-4;
  cfg.plant = plant;
  return cfg;
}

// Stages a T-curve move (pulse, pulse/tick, pulse/tick^2) on axis i and updates that axis.
inline void t_move(machine::Card& c, std::size_t i, double pos, double vel, double acc) {
  c.stage_acc(i, acc);
  c.stage_vel(i, vel);
  c.stage_pos(i, pos);
  c.update(1u << i);
}

}  // namespace servobench::test
