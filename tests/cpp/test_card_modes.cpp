// The card's driven modes: electronic gear (GT TV10/TV11), a GUC/iDEABOX coordinate system on the card, PVT and
// FollowEx axes, faults stopping them, the coordinate-system status words.
// Manuals: GT seed 000 (gt.md §3.4, §4.6), GUC-ECAT seed 002 (guc-ecat.md §2, §6), iDEABOX seed 003.
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/machine/card.hpp"
#include "card_fixtures.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/googol/crd_status.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;
namespace sm = servobench::motion;

namespace {

mc::AxisConfig tuned_axis(double period_s = 200e-6) { return servobench::test::tuned_axis(period_s); }

void t_move(mc::Card& c, std::size_t i, double pos, double vel, double acc) {
  c.stage_acc(i, acc);
  c.stage_vel(i, vel);
  c.stage_pos(i, pos);
  c.update(1u << i);
}

void all_on(mc::Card& c) {
  for (std::size_t i = 0; i < c.axis_count(); ++i) c.axis_on(i);
}

}  // namespace

TEST(CardModes, GearTv10SlaveMirrorsTheMasterAndBit10StaysSet) {
  // GT L1055-1059 (TV10): axis 1 PrflG(2), Ratio -1, Update -> dpos1 = -dpos2; bit 10 of axis 1 always 1 (L1090).
  mc::Card c(4, tuned_axis());
  all_on(c);
  c.modes().set_gear(0, 1);
  c.stage_ratio(0, -1);
  c.update(1u);
  EXPECT_EQ(c.state(0).mode, mc::AxisMode::Gear);
  EXPECT_EQ(vg::gt_mode_register(c, 0) >> 11 & 7, 3);
  c.run(10);
  EXPECT_TRUE(vg::gt_axis_status(c, 0) & (1u << 10));  // master at rest, slave "moving"
  t_move(c, 1, 20000, 2, 0.01);
  double max_err = 0;
  for (int k = 0; k < 12000; ++k) {
    const long long master_before = c.profile_pos(1);
    c.run(1);
    EXPECT_EQ(c.profile_pos(0), -master_before);  // numbered below its master: one tick late (V51)
    max_err = std::max(max_err, std::fabs(c.following_error(0)));
  }
  EXPECT_EQ(c.profile_pos(1), 20000);
  EXPECT_NEAR(c.actual_pos(0), -20000, 2);  // the slave's loop tracks
  EXPECT_LT(max_err, 20);
  EXPECT_TRUE(vg::gt_axis_status(c, 0) & (1u << 10));
  // invalid in gear mode (GT L1144, L1421-1429): SmthStp, ZeroPos, SynchPos, profile moves
  EXPECT_THROW(c.stage_smooth_stop(0), mc::CardCommandRefused);
  EXPECT_THROW(c.zero_pos(0), mc::CardCommandRefused);
  c.stage_synch_pos(0);
  EXPECT_THROW(c.update(1u), mc::CardCommandRefused);
}

TEST(CardModes, GearTv11ChainFollowsWithTheRatios) {
  // GT L4421-4435 (TV11): axis 4 T-curve; axis 1 PrflG(4) ratio -1.5; axis 3 PrflG(1) ratio 0.5; MltiUpdt(0x5).
  mc::Card c(4, tuned_axis());
  all_on(c);
  c.modes().set_gear(0, 3);
  c.stage_ratio(0, -1.5);
  c.modes().set_gear(2, 0);
  c.stage_ratio(2, 0.5);
  c.update(0x5);
  t_move(c, 3, 10000, 1, 0.01);
  c.run(10200);
  EXPECT_EQ(c.profile_pos(3), 10000);
  EXPECT_EQ(c.profile_pos(0), -15000);
  EXPECT_EQ(c.profile_pos(2), -7500);
  EXPECT_NEAR(c.actual_pos(2), -7500, 2);
}

TEST(CardModes, GearSlaveLimitStopsTheMaster) {
  // GT L1082: a slave's abnormal status (limit, alarm) stops the master unless the master is open loop.
  mc::Card c(4, tuned_axis());
  all_on(c);
  c.modes().set_gear(0, 1);
  c.stage_ratio(0, 1);
  c.update(1u);
  t_move(c, 1, 100000, 2, 0.01);
  c.run(2000);
  ASSERT_TRUE(c.loop(1).generator().moving());
  c.set_alarm_input(0, true);
  c.run(3);
  EXPECT_TRUE(c.modes().gear_halted(0));
  EXPECT_FALSE(c.loop(1).generator().moving());
  EXPECT_FALSE(vg::gt_axis_status(c, 0) & (1u << 10));  // bit 10 clears on the abnormal stop (L1090)
  // mode change and a new PrflG recover
  EXPECT_THROW(c.modes().set_gear(0, 0), mc::CardCommandRefused);  // its own master
}

TEST(CardModes, GearSlaveAtALimitRestrictsTheMastersDirection) {
  // GT L2213: slave negative limit + negative ratio -> the master may move only negative.
  mc::Card c(4, tuned_axis());
  all_on(c);
  c.modes().set_gear(0, 1);
  c.stage_ratio(0, -1);
  c.update(1u);
  mc::LimitConfig lim;
  lim.soft_neg_enabled = true;
  lim.soft_neg_pulse = 0;  // the slave stands on its negative (soft) limit
  c.set_limits(0, lim);
  c.run(2);
  ASSERT_TRUE(c.events(0) & mc::event_bit(mc::CardEvent::SoftNegLimit));
  c.stage_acc(1, 0.01);
  c.stage_vel(1, 1);
  c.stage_pos(1, 1000);
  EXPECT_THROW(c.update(2u), mc::CardCommandRefused);
  EXPECT_EQ(c.last_fault(), mc::CommandFault::DirectionInhibited);
  c.stage_pos(1, -1000);
  EXPECT_NO_THROW(c.update(2u));
  c.run(2000);
  EXPECT_EQ(c.profile_pos(1), -1000);
  EXPECT_EQ(c.profile_pos(0), 1000);
}

TEST(CardModes, CrdPairOnTheCardRunsTheHexagonSideAndTracks) {
  // GUC L802-843 (guc-ecat.md §6.2): a 200000-pulse side at v 100 pulse/ms, a 0.1 takes 3000 ms (15000 ticks).
  mc::Card c(8, tuned_axis());
  all_on(c);
  sm::CrdPrm prm;
  prm.dimension = 2;
  prm.profile[0] = 1;
  prm.profile[1] = 2;
  prm.syn_vel_max = 500;
  prm.syn_acc_max = 1;
  c.modes().set_crd_prm(1, prm);
  EXPECT_EQ(c.state(0).mode, mc::AxisMode::Coordinated);
  EXPECT_EQ(c.state(2).mode, mc::AxisMode::TCurve);
  c.modes().crd(1).fifo(0).line({200000, 0, 0, 0}, 100, 0.1);
  // a T-curve move on a crd axis is refused (GT L1659: independent commands invalid in coordinated mode)
  c.stage_pos(0, 10);
  EXPECT_THROW(c.update(1u), mc::CardCommandRefused);
  c.modes().crd_start(1u, 0u);
  EXPECT_EQ(vg::guc_crd_status(c, 1, 0).run, 1);
  c.run(14995);
  EXPECT_EQ(vg::guc_crd_status(c, 1, 0).run, 1);
  c.run(10);
  EXPECT_EQ(vg::guc_crd_status(c, 1, 0).run, 0);
  EXPECT_EQ(vg::guc_crd_status(c, 1, 0).segment, 1);
  EXPECT_EQ(c.profile_pos(0), 200000);
  EXPECT_EQ(c.profile_pos(1), 0);
  c.run(1000);
  EXPECT_NEAR(c.actual_pos(0), 200000, 2);
  EXPECT_FALSE(c.moving(0));
}

TEST(CardModes, AxisFaultStopsThePathAndTheStatusShowsIt) {
  mc::Card c(4, tuned_axis(1e-3));
  all_on(c);
  sm::CrdPrm prm;
  prm.dimension = 2;
  prm.profile[0] = 1;
  prm.profile[1] = 2;
  prm.syn_vel_max = 500;
  prm.syn_acc_max = 1;
  c.modes().set_crd_prm(1, prm);
  c.modes().crd(1).fifo(0).line({200000, 100000, 0, 0}, 100, 0.1);
  c.modes().crd_start(1u, 0u);
  c.run(1500);
  c.set_alarm_input(1, true);  // drive alarm on Y
  c.run(2);
  const mc::HostedGroup& h = c.modes().hosted(0);
  EXPECT_TRUE(h.fault_stopped);
  EXPECT_EQ(h.fault_cause, mc::StopCause::DriveAlarm);
  EXPECT_EQ(vg::guc_crd_status(c, 1, 0).run, 0);
  const auto x = c.profile_pos(0);
  c.run(100);
  EXPECT_EQ(c.profile_pos(0), x);  // X stopped with the path
  // a start is refused while the alarm is active
  EXPECT_THROW(c.modes().crd_start(1u, 0u), mc::CardCommandRefused);
  vg::CrdStatusInputs in;
  in.fault_stopped = h.fault_stopped;
  EXPECT_EQ(vg::gt_crd_status(in), 0x02D3);  // bits 0, 1, 4, 6, 7, 9
  EXPECT_EQ(vg::ge_crd_status(in), 0x2293);  // bits 0, 1, 4, 7, 9, 13
}

TEST(CardModes, PvtAxisOnTheCard) {
  // GUC L1506-1604 (guc-ecat.md §6.7): t=600 ms p 2737.5; end 68966.
  mc::Card c(4, tuned_axis());
  all_on(c);
  c.modes().pvt_download(1, sm::pvt_table({0, 1200, 2000, 3000, 3800, 5000}, {0, 9750, 24483, 44483, 59216, 68966},
                                          {1, 15.25, 20, 20, 15.25, 1}));
  c.modes().set_pvt(0);
  EXPECT_EQ(c.state(0).mode, mc::AxisMode::Pvt);
  c.modes().pvt_start(1u);
  c.run(3000);  // 600 ms at 0.2 ms per tick
  EXPECT_NEAR(c.loop(0).generator().state().pos, 2737.5, 1e-6);
  c.run(22000);
  EXPECT_NEAR(c.loop(0).generator().state().pos, 68966, 1e-6);
  c.run(1000);
  EXPECT_FALSE(c.moving(0));
  EXPECT_NEAR(c.actual_pos(0), 68966, 2);
}
