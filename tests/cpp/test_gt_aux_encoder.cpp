// The GT auxiliary encoders (vendor/googol/gt_aux_encoder.hpp; GT manual L3124-3136, L3241-3330, L3727-3759,
// L4733-4747, EncSns L595-635; decisions GT8, GZ1-GZ5): the index arithmetic, the position / velocity / zero /
// sense registers and the capture state machine, with the machine's counts given by a C++ function of t_s.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/gt_aux_encoder.hpp"
#include "servobench/vendor/googol/gt_card.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;
using vg::GtCode;

namespace {

// Encoder n counts floor(offset_n + rate_n t) (pulse); marks on encoder 1 every 4000 counts from 1000.
vg::AuxInputs ramp(double offset0, double rate0, double offset1 = 0.0, double rate1 = 0.0, int reversed = 0) {
  vg::AuxInputs in;
  in.counts = [=](int n, double t) {
    return static_cast<long long>(std::floor(n == 0 ? offset0 + rate0 * t : offset1 + rate1 * t));
  };
  in.reversed = reversed;
  in.counts_per_index = 4000;
  in.index_offset = 1000.0;
  return in;
}

}  // namespace

TEST(GtAuxEncoder, IndexMarkIsTheFirstInTheDirectionOfTravel) {
  EXPECT_EQ(vg::index_mark_between(-3000, 3000, 4000, 1000.0), std::optional<long long>(1000));
  EXPECT_EQ(vg::index_mark_between(3000, -3000, 4000, 1000.0), std::optional<long long>(1000));
  EXPECT_EQ(vg::index_mark_between(1000, 4999, 4000, 1000.0), std::nullopt);   // the mark it starts on is not met
  EXPECT_EQ(vg::index_mark_between(1000, 5000, 4000, 1000.0), std::optional<long long>(5000));
  EXPECT_EQ(vg::index_mark_between(1000, -3000, 4000, 1000.0), std::optional<long long>(-3000));
  EXPECT_EQ(vg::index_mark_between(10, 10, 4000, 1000.0), std::nullopt);        // no motion
  EXPECT_EQ(vg::index_mark_between(0, 100000, 0, 0.0), std::nullopt);          // no index mark
  EXPECT_EQ(vg::index_mark_between(0, 10, 7, 2.5), std::optional<long long>(2));  // mark 2.5 -> count 2
  EXPECT_EQ(vg::index_mark_between(3, 10, 7, 2.5), std::optional<long long>(9));  // mark 9.5 -> count 9
  EXPECT_THROW(vg::index_mark_between(0, 10, -1, 0.0), std::invalid_argument);
}

TEST(GtAuxEncoder, PositionVelocityAndClear) {
  mc::Card card(4, servobench::test::tuned_axis());  // ST = 200 us
  vg::GtCard& g = vg::gt(card);
  const vg::AuxInputs in = ramp(0.0, 0.0, 0.0, 25000.0);  // encoder 2: 5 pulse/ST
  card.run(100);
  EXPECT_EQ(g.aux_position(2, in), std::make_pair(GtCode::Success, 500LL));
  EXPECT_EQ(g.aux_velocity(2, in), std::make_pair(GtCode::Success, 5.0));
  EXPECT_EQ(g.clear_aux_position(2, in), GtCode::Success);
  EXPECT_EQ(g.aux_position(2, in).second, 0);
  EXPECT_EQ(g.aux().zero()[1], 500);
  card.run(10);
  EXPECT_EQ(g.aux_position(2, in).second, 50);
  EXPECT_EQ(g.aux_position(3, in), std::make_pair(GtCode::ParameterError, 0LL));
  EXPECT_EQ(card.last_fault(), mc::CommandFault::IllegalControlParam);
  EXPECT_EQ(g.aux_velocity(0, in).first, GtCode::ParameterError);
  EXPECT_EQ(g.clear_aux_position(1.5, in), GtCode::CommError);  // "-1 failure" (L3130)
  vg::AuxInputs none;  // nothing connected: 0
  EXPECT_EQ(g.aux_position(1, none).second, 0);
}

TEST(GtAuxEncoder, VelocityAtTickZeroIsZero) {
  mc::Card card(4, servobench::test::tuned_axis());
  EXPECT_EQ(vg::gt(card).aux_velocity(1, ramp(7.0, 1e6)).second, 0.0);  // max(0, t - ST): both reads at t = 0
}

TEST(GtAuxEncoder, SenseReversesTheCountKeepingTheRead) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  vg::AuxInputs in = ramp(100.0, 0.0, 0.0, 0.0, /*reversed=*/0x3);  // axes 1, 2 wired against the motor
  EXPECT_EQ(g.set_encoder_sense(0, in), GtCode::CommandError);       // positive feedback: not simulated
  EXPECT_EQ(card.last_fault(), mc::CommandFault::NotSimulated);
  EXPECT_EQ(g.set_encoder_sense(3, in), GtCode::Success);
  EXPECT_EQ(g.aux_position(1, in).second, 100);
  EXPECT_EQ(g.set_encoder_sense(0x13, in), GtCode::Success);
  EXPECT_EQ(g.aux_position(1, in).second, 100);                      // the read stays ...
  card.run(5);
  in = ramp(100.0, 1e4, 0.0, 0.0, 0x3);                              // ... and now counts down as it turns up
  EXPECT_EQ(g.aux_position(1, in).second, 100 - static_cast<long long>(std::floor(100 + 1e4 * 5 * 200e-6)) + 100);
  EXPECT_EQ(g.set_encoder_sense(0x40, in), GtCode::ParameterError);
  EXPECT_EQ(g.set_encoder_sense(-1, in), GtCode::ParameterError);
}

TEST(GtAuxEncoder, CaptureLatchesTheFirstIndexMarkAfterArming) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  const vg::AuxInputs in = ramp(-3000.0, 20000.0);  // 4 pulse/ST; marks at 1000 + 4000 k
  EXPECT_EQ(g.aux_capture_status(in), std::make_pair(GtCode::Success, 0));
  EXPECT_EQ(g.aux_capture_value(in), std::make_pair(GtCode::Success, 0LL));
  EXPECT_EQ(g.arm_aux_capture(in), GtCode::Success);
  EXPECT_TRUE(g.aux().capture().armed);
  card.run(500);  // -3000 -> -1000: the mark at -3000 is where it starts
  EXPECT_EQ(g.aux_capture_status(in).second, 0);
  card.run(1000);  // to 3000: the mark at 1000 is crossed
  EXPECT_EQ(g.aux_capture_status(in).second, 0x8);
  EXPECT_EQ(g.aux_capture_value(in).second, 1000);
  EXPECT_FALSE(g.aux().capture().armed);
  EXPECT_EQ(g.aux().capture().tick, 1500);  // the scan caught up with the card
  card.run(1000);  // past 5000: held until armed again
  EXPECT_EQ(g.aux_capture_value(in).second, 1000);
  EXPECT_EQ(g.arm_aux_capture(in), GtCode::Success);
  EXPECT_EQ(g.aux_capture_status(in).second, 0);
  EXPECT_EQ(g.aux_capture_value(in).second, 1000);  // the previous value until the next capture (L3731)
  card.run(1000);
  EXPECT_EQ(g.aux_capture_value(in).second, 9000);
}

TEST(GtAuxEncoder, CaptureUsesTheSenseAndZeroAtTheRead) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  const vg::AuxInputs in = ramp(-3000.0, 20000.0);
  ASSERT_EQ(g.arm_aux_capture(in), GtCode::Success);
  card.run(1500);
  ASSERT_EQ(g.set_encoder_sense(0x10, in), GtCode::Success);  // reversed, the read kept: zero = -2 raw
  const long long zero = g.aux().zero()[0];
  EXPECT_EQ(zero, -2 * 3000);
  EXPECT_EQ(g.aux_capture_value(in).second, -1000 - zero);  // sign -1 times the mark 1000, minus the zero
}

TEST(GtAuxEncoder, ResetKeepsTheZeroAndTheCapture) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  const vg::AuxInputs in = ramp(0.0, 0.0, 70.0, 0.0);
  ASSERT_EQ(g.clear_aux_position(2, in), GtCode::Success);
  ASSERT_EQ(g.arm_aux_capture(in), GtCode::Success);
  ASSERT_EQ(g.hard_reset(), GtCode::Success);  // GT6
  EXPECT_EQ(g.aux().zero()[1], 70);
  EXPECT_TRUE(g.aux().capture().armed);
}
