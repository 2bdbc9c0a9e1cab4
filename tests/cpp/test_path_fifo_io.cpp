// FIFO0 / FIFO1 of a coordinate system, buffered limit switches and stop inputs, and the GE start velocity.
// Manual files in ../shared/seeds/: GE = 001_b26ef06a365efe59.txt, GUC = 002_b2237d67fd2eb602.txt (digest
// guc-ecat.md §2.2, §2.5), iDEABOX = 003_2c62cffc310de7fb.txt (ideabox.md §2.2, §6 item 6). Units: pulse, ms,
// pulse/ms, pulse/ms^2; 1 ms motion cycle.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "servobench/motion/crd_fifo_pair.hpp"
#include "servobench/motion/generator.hpp"

namespace sm = servobench::motion;
using P = sm::CrdPoint;

namespace {
template <class G>
long run_until(G& g, long max_ticks, bool (*pred)(const G&)) {
  long k = 0;
  for (; k < max_ticks && !pred(g); ++k) g.step();
  return k;
}
bool pair_idle(const sm::CrdFifoPair& p) { return !p.running(); }
}  // namespace

TEST(PathFifo1, IdeaboxEx4_6_ToolChangeThroughFifo1ThenResume) {
  // iDEABOX Ex 4-6 (L1713-1900): FIFO0 line to (100000, 100000) at 10 pulse/ms, 1 pulse/ms^2; stopped
  // (GT_StopMx bit 12 with the abrupt option) once X > 50000; FIFO1: (70000, 30000), (110000, 50000), started;
  // then back to the DINT-rounded stop position, started again; then FIFO0 resumes and ends at (100000, 100000).
  sm::CrdFifoPair pair(sm::CoordSystem::identity(2));
  pair.fifo(0).line({100000, 100000}, 10, 1);
  pair.start(0);
  while (pair.state().pos[0] <= 50000.0) pair.step();
  pair.stop(true);
  run_until<sm::CrdFifoPair>(pair, 10, pair_idle);
  const P stop = pair.state().pos;
  EXPECT_GT(stop[0], 50000.0);
  EXPECT_LT(stop[0], 50000.0 + 10.0);
  // Data to FIFO1 while FIFO0 is stopped: accepted; its first segment starts at the stop position.
  pair.fifo(1).line({70000, 30000}, 10, 1);
  pair.fifo(1).line({110000, 50000}, 10, 1);
  pair.start(1);
  EXPECT_EQ(pair.active(), 1);
  // FIFO0 cannot start while FIFO1 moves (iDEABOX L4558-4566: return 1).
  pair.step();
  EXPECT_THROW(pair.start(0), sm::MotionCommandRefused);
  run_until<sm::CrdFifoPair>(pair, 100000, pair_idle);
  EXPECT_DOUBLE_EQ(pair.state().pos[0], 110000);
  EXPECT_DOUBLE_EQ(pair.state().pos[1], 50000);
  // Away from the breakpoint FIFO0 refuses to resume (GUC L1005, iDEABOX L1648-1653, L4560: return 1) and
  // FIFO1 keeps its data (nothing was started).
  EXPECT_THROW(pair.start(0), sm::MotionCommandRefused);
  // Back to LREAL_TO_DINT(stop position), started as a second FIFO1 program (L1860-1880).
  pair.fifo(1).line({std::round(stop[0]), std::round(stop[1])}, 10, 1);
  pair.start(1);
  run_until<sm::CrdFifoPair>(pair, 100000, pair_idle);
  EXPECT_EQ(pair.fifo(1).state().segments_done, 3);
  pair.start(0);  // within 0.5 pulse per coordinate of the breakpoint (decision C26)
  EXPECT_EQ(pair.active(), 0);
  run_until<sm::CrdFifoPair>(pair, 100000, pair_idle);
  EXPECT_DOUBLE_EQ(pair.state().pos[0], 100000);
  EXPECT_DOUBLE_EQ(pair.state().pos[1], 100000);
  EXPECT_EQ(pair.fifo(0).state().segments_done, 1);
}

TEST(PathFifo1, PushRulesAndSuspendedFifo1IsClearedByFifo0) {
  // GUC L997-1005, iDEABOX L1640-1642: data to FIFO1 while FIFO0 moves returns 1; FIFO1 can be suspended and
  // resumed, but running FIFO0 in between clears it.
  sm::CrdFifoPair pair(sm::CoordSystem::identity(2));
  pair.fifo(0).line({10000, 0}, 10, 1);
  pair.fifo(0).line({10000, 10000}, 10, 1);
  pair.start(0);
  pair.step();
  EXPECT_THROW(pair.fifo(1).line({0, 5000}, 10, 1), sm::MotionCommandRefused);
  EXPECT_THROW(pair.fifo(1).buf_io(0, 1, 1), sm::MotionCommandRefused);
  EXPECT_THROW(pair.fifo(1).buf_lmts(1, -1, false), sm::MotionCommandRefused);
  EXPECT_THROW(pair.start(1), sm::MotionCommandRefused);
  for (int k = 0; k < 500; ++k) pair.step();
  pair.stop(false);
  run_until<sm::CrdFifoPair>(pair, 1000, pair_idle);
  const P brk = pair.state().pos;
  ASSERT_TRUE(pair.fifo(0).has_breakpoint());
  // FIFO1: out and back, suspended half way out.
  pair.fifo(1).line({brk[0], brk[1] + 5000}, 10, 1);
  pair.fifo(1).line({brk[0], brk[1]}, 10, 1);
  pair.start(1);
  for (int k = 0; k < 300; ++k) pair.step();
  pair.stop(true);
  pair.step();
  EXPECT_TRUE(pair.fifo(1).has_breakpoint());
  EXPECT_EQ(pair.fifo(1).remaining_segments(), 2);
  // Resuming FIFO1 works (it is at its own breakpoint) ...
  pair.start(1);
  for (int k = 0; k < 100; ++k) pair.step();
  pair.stop(true);
  pair.step();
  // ... but FIFO0 cannot start away from its breakpoint, and FIFO1 is not cleared by the refusal.
  EXPECT_THROW(pair.start(0), sm::MotionCommandRefused);
  EXPECT_EQ(pair.fifo(1).remaining_segments(), 2);
  pair.start(1);
  run_until<sm::CrdFifoPair>(pair, 100000, pair_idle);
  EXPECT_NEAR(pair.state().pos[1], brk[1], 1e-9);
  // A second suspended FIFO1 program is lost when FIFO0 runs.
  pair.fifo(1).line({brk[0] - 1000, brk[1]}, 10, 1);
  pair.fifo(1).line({brk[0], brk[1]}, 10, 1);
  pair.start(1);
  pair.stop(true);  // suspended at once, at the breakpoint of FIFO0
  pair.step();
  EXPECT_EQ(pair.fifo(1).remaining_segments(), 2);
  pair.start(0);
  EXPECT_EQ(pair.fifo(1).remaining_segments(), 0);
  EXPECT_FALSE(pair.fifo(1).has_breakpoint());
  run_until<sm::CrdFifoPair>(pair, 100000, pair_idle);
  EXPECT_DOUBLE_EQ(pair.state().pos[0], 10000);
  EXPECT_DOUBLE_EQ(pair.state().pos[1], 10000);
  // FIFO1 has its own look-ahead (GUC L999, iDEABOX L1673-1675).
  pair.fifo(1).init_lookahead({5, 1, 50});
  EXPECT_TRUE(pair.fifo(1).lookahead_on());
  EXPECT_FALSE(pair.fifo(0).lookahead_on());
}

TEST(PathBufferedIo, BufLmtsOnOffAreBufferedStateChanges) {
  // GUC L609-624, iDEABOX L4270-4330: limitType 0 positive, 1 negative, -1 both; executed in FIFO order.
  sm::PathGenerator g(sm::CoordSystem::identity(2));
  EXPECT_EQ(g.state().limits_pos, 0xFFFFu);
  EXPECT_EQ(g.state().limits_neg, 0xFFFFu);
  g.line({1000, 0}, 10, 1);
  g.buf_lmts(3, -1, false);
  g.line({1000, 1000}, 10, 1);
  g.buf_lmts(3, 0, true);
  g.buf_lmts(5, 1, false);
  g.line({0, 1000}, 10, 1);
  EXPECT_EQ(g.state().limits_pos, 0xFFFFu);  // nothing executes before the start
  g.start();
  std::vector<std::pair<long long, std::uint32_t>> seen;
  while (!g.done()) {
    const auto& s = g.step();
    if (seen.empty() || seen.back().second != (s.limits_pos | (s.limits_neg << 16)))
      seen.push_back({s.segments_done, s.limits_pos | (s.limits_neg << 16)});
  }
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0].second, 0xFFFFFFFFu);
  EXPECT_EQ(seen[1].first, 1);  // after segment 1: axis 3 both off
  EXPECT_EQ(seen[1].second, 0xFFFBFFFBu);
  EXPECT_EQ(seen[2].first, 2);  // after segment 2: axis 3 positive on, axis 5 negative off
  EXPECT_EQ(seen[2].second, 0xFFEBFFFFu);
  EXPECT_THROW(g.buf_lmts(0, -1, true), std::invalid_argument);
  EXPECT_THROW(g.buf_lmts(17, -1, true), std::invalid_argument);
  EXPECT_THROW(g.buf_lmts(1, 2, true), std::invalid_argument);
}

TEST(PathBufferedIo, BufSetStopIoStopsThePathWithItsStopType) {
  // GUC L625-645: stopType 0 emergency, 1 smooth; inputType 0 +limit .. 4 GPI; armed at its FIFO position.
  auto make = [](int stop_type) {
    sm::PathSetup setup;
    setup.stop_dec_smooth = 0.5;
    sm::PathGenerator g(sm::CoordSystem::identity(2), setup);
    g.line({20000, 0}, 20, 1);
    g.buf_set_stop_io(2, stop_type, 4, 7);  // axis 2 (Y, in the coordinate system) stops on GPI 7
    g.line({20000, 20000}, 20, 1);
    return g;
  };
  for (int stop_type : {0, 1}) {
    auto g = make(stop_type);
    g.set_input(4, 7, true);  // active from the start: nothing happens before the mapping executes
    g.start();
    while (g.state().segments_done == 0) g.step();
    EXPECT_DOUBLE_EQ(g.state().pos[0], 20000);
    EXPECT_TRUE(g.stop_io(2).armed);
    for (int k = 0; k < 30 && !g.stopped(); ++k) g.step();
    EXPECT_TRUE(g.stopped());  // at the start of segment 2 (at most a few pulse along it)
    EXPECT_LT(g.state().pos[1], 25.0);
    EXPECT_EQ(g.state().io_stop_axis, 2);
    // Released, resumed, and the input comes back at full speed.
    g.set_input(4, 7, false);
    g.start();
    for (int k = 0; k < 400; ++k) g.step();
    EXPECT_NEAR(g.state().speed, 20.0, 1e-9);
    g.set_input(4, 7, true);
    g.step();
    if (stop_type == 0) {
      // Emergency stop with stop_dec_abrupt 0: at rest in the same cycle (GT EStpMtn rule, decision C21).
      EXPECT_TRUE(g.stopped());
      EXPECT_EQ(g.state().speed, 0.0);
    } else {
      // Smooth stop at stop_dec_smooth 0.5 pulse/ms^2: 40 ms from 20 pulse/ms.
      EXPECT_FALSE(g.stopped());
      EXPECT_NEAR(g.state().speed, 19.5, 1e-9);
      int n = 1;
      for (; n < 100 && !g.stopped(); ++n) {
        g.step();
        EXPECT_GE(g.state().acc, -0.5 - 1e-12);
      }
      EXPECT_NEAR(n, 41, 1);
    }
    g.set_input(4, 7, false);
    g.start();
    while (!g.done()) g.step();
    EXPECT_DOUBLE_EQ(g.state().pos[1], 20000);
  }
}

TEST(PathBufferedIo, LimitStopInputCountsOnlyWhileTheLimitIsEnabled) {
  // BufSetStopIo on the +limit of axis 1, then BufLmtsOff of that limit: the active input no longer stops.
  sm::PathGenerator g(sm::CoordSystem::identity(2));
  g.buf_set_stop_io(1, 0, 0, 1);
  g.buf_lmts(1, 0, false);
  g.line({5000, 0}, 10, 1);
  g.buf_lmts(1, 0, true);
  g.line({5000, 5000}, 10, 1);
  g.set_input(0, 1, true);
  g.start();
  while (g.state().segments_done == 0 && !g.stopped()) g.step();
  EXPECT_FALSE(g.stopped());
  EXPECT_DOUBLE_EQ(g.state().pos[0], 5000);
  for (int k = 0; k < 3; ++k) g.step();
  EXPECT_TRUE(g.stopped());  // the limit is enabled again after segment 1
  EXPECT_EQ(g.state().io_stop_axis, 1);
}

TEST(PathBufferedIo, StopInputOfAnOutsideAxisAbortsItsModalMoveAndHaltsTheFifo) {
  // GUC L1055, iDEABOX L2344-2348: a modal BufMove aborted (e.g. by a limit) halts the rest of the FIFO.
  sm::PathGenerator g(sm::CoordSystem::identity(2));
  g.buf_set_stop_io(4, 0, 2, 4);  // axis 4 stops on its alarm input
  g.buf_move(4, 50000, 30, 0.1, true);
  g.line({1000, 0}, 10, 1);
  g.start();
  for (int k = 0; k < 200; ++k) g.step();
  EXPECT_GT(g.aux_position(4), 0.0);
  g.set_input(2, 4, true);
  g.step();
  const double held = g.aux_position(4);
  EXPECT_TRUE(g.stopped());
  EXPECT_EQ(g.state().io_stop_axis, 4);
  for (int k = 0; k < 100; ++k) g.step();
  EXPECT_EQ(g.aux_position(4), held);  // emergency stop: the axis holds
  EXPECT_EQ(g.state().pos[0], 0.0);    // the line after the modal move did not run
  EXPECT_THROW(g.buf_set_stop_io(9, 0, 0, 1), std::invalid_argument);
  EXPECT_THROW(g.buf_set_stop_io(1, 2, 0, 1), std::invalid_argument);
  EXPECT_THROW(g.buf_set_stop_io(1, 0, 5, 1), std::invalid_argument);
  EXPECT_THROW(g.buf_set_stop_io(1, 0, 0, 9), std::invalid_argument);
  EXPECT_NO_THROW(g.buf_set_stop_io(1, 0, 4, 16));
  EXPECT_THROW(g.set_input(4, 17, true), std::invalid_argument);
}

TEST(PathStartVel, GeSegmentsLeaveAndReachRestAtTheStartVelocity) {
  // GE L1395-1399 (GT_SetStrtVel: start velocity, default 500 Hz = 0.5 pulse/ms, GE L5754), L1473-1477 (G0:
  // from the start velocity up to the feed, down to the start velocity, then stop), L1660 (RestoreMtn:
  // decelerates to the start velocity). GE Ex 6-1 (L1349-1357): StartVel 0.3 pulse/ms, feed 100, acc 1.8.
  sm::PathSetup setup;
  setup.start_vel = 0.3;
  sm::PathGenerator g(sm::CoordSystem::identity(2), setup);
  g.line({10000, 0}, 100, 1.8, 0.0, /*g0=*/true);
  g.start();
  std::vector<double> v;
  while (!g.done()) v.push_back(g.step().speed);
  // First cycle: 0.3 + 1.8 (one cycle of ramp); the speed never falls below 0.3 while moving.
  EXPECT_NEAR(v.front(), 0.3 + 1.8, 1e-9);
  double vmin = 1e9;
  for (std::size_t k = 0; k + 1 < v.size(); ++k) vmin = std::min(vmin, v[k]);
  EXPECT_GE(vmin, 0.3 - 1e-9);
  EXPECT_EQ(v.back(), 0.0);
  EXPECT_DOUBLE_EQ(g.state().pos[0], 10000);
  // Duration: ramps of (100 - 0.3) / 1.8 ms each side, cruise for the rest.
  const double tr = (100 - 0.3) / 1.8, dr = (100 * 100 - 0.3 * 0.3) / (2 * 1.8);
  EXPECT_NEAR(static_cast<double>(v.size()), 2 * tr + (10000 - 2 * dr) / 100, 1.0);
  // Without a start velocity the same move is slower by about 0.3/1.8 ms per ramp and starts from 0.
  sm::PathGenerator h(sm::CoordSystem::identity(2));
  h.line({10000, 0}, 100, 1.8, 0.0, true);
  h.start();
  EXPECT_NEAR(h.step().speed, 1.8, 1e-9);
  sm::PathSetup bad;
  bad.start_vel = -1;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}
