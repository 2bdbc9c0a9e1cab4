// Issue 21.2/21.4: validated ranges (upper bounds, the inertia floor) and protections that trip on a non-finite
// following error.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "card_fixtures.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/axis.hpp"
#include "servobench/machine/card.hpp"

namespace mc = servobench::machine;
using servobench::test::tuned_axis;

namespace {
const double kNan = std::numeric_limits<double>::quiet_NaN();

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Guards, UpperBoundsAndTheInertiaFloorAreStated) {
  servobench::drive::TorqueDriveParams d;
  d.current_bw_hz = 1e20;
  EXPECT_NE(message_of([&] { d.validate(); }).find("current_bw_hz = 1e+20 must be > 0 and <= 1000000"),
            std::string::npos);
  d.current_bw_hz = servobench::drive::kInf;  // ideal: allowed
  EXPECT_NO_THROW(d.validate());
  servobench::plant::RigidPlantParams p;
  p.inertia_kgm2 = 1e-300;
  EXPECT_NE(message_of([&] { p.validate(); }).find("at least 1e-09"), std::string::npos);
  p.inertia_kgm2 = kNan;
  EXPECT_NE(message_of([&] { p.validate(); }).find("not a finite number"), std::string::npos);
  EXPECT_THROW(servobench::check_positive("X", "y", 1e300), std::invalid_argument);
  EXPECT_THROW(servobench::check_nonnegative("X", "y", -0.5), std::invalid_argument);
  EXPECT_NO_THROW(servobench::check_positive_or_inf("X", "y", std::numeric_limits<double>::infinity()));
}

TEST(Guards, ANonFiniteErrorTripsTheRunGuard) {
  // |e| > limit is false for NaN; the guard is written !(|e| <= limit) so a NaN error turns the servo off.
  mc::Axis axis(tuned_axis());
  const std::vector<double> cmd = {0.0, 0.0, kNan, 0.0, 0.0};
  mc::CommandInput in;
  in.pos = cmd.data();
  in.n = cmd.size();
  mc::RunGuard guard;
  guard.error_limit_pulse = 1000.0;
  const mc::RunOutcome out = axis.run(in, mc::Trace{}, guard);
  EXPECT_EQ(out.stop, mc::RunStop::kErrorLimit);
  EXPECT_EQ(out.ticks, 3u);
  EXPECT_FALSE(axis.servo_on());
}

TEST(Guards, AnEncoderFaultIsAFollowingErrorThatStopsWithAutoStop) {
  mc::Card card(4, tuned_axis());
  card.axis_on(0);
  card.set_auto_stop(0, true);
  card.run(10);
  ASSERT_TRUE(card.servo_on(0));
  card.set_encoder_fault(0, true);
  card.run(1);
  EXPECT_NE(card.state(0).events & (1u << static_cast<int>(mc::CardEvent::FollowingError)), 0u);
  EXPECT_FALSE(card.servo_on(0));
}
