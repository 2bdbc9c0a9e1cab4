// Thread stress (issue 21.1): threads x objects x operations under the bindings' lock protocol
// (cpp/bindings/lock_table.hpp): a run holds the object's run lock and steps in chunks under its state lock;
// every other operation takes the state lock. Run by scripts/test.sh under ThreadSanitizer too (build/tsan),
// where any data race in the core or the protocol fails the test.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "../../cpp/bindings/lock_table.hpp"
#include "card_fixtures.hpp"
#include "servobench/machine/axis.hpp"
#include "servobench/machine/batch.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_scope.hpp"

namespace mc = servobench::machine;
using servobench::bindings::locks_of;
using servobench::test::t_move;
using servobench::test::tuned_axis;

namespace {

// Card.run as the binding does it: the run lock for the whole run, the state lock per chunk.
void locked_card_run(mc::Card& card, std::size_t ticks, std::size_t chunk) {
  auto locks = locks_of(&card);
  std::lock_guard<std::recursive_mutex> run(locks->run);
  for (std::size_t done = 0; done < ticks; done += chunk) {
    std::lock_guard<std::recursive_mutex> state(locks->state);
    card.run(std::min(chunk, ticks - done));
  }
}

// Axis.run as the binding does it.
std::vector<double> locked_axis_run(mc::Axis& axis, const std::vector<double>& cmd, std::size_t chunk) {
  auto locks = locks_of(&axis);
  std::lock_guard<std::recursive_mutex> run(locks->run);
  std::vector<double> err(cmd.size());
  for (std::size_t done = 0; done < cmd.size(); done += chunk) {
    std::lock_guard<std::recursive_mutex> state(locks->state);
    mc::CommandInput in;
    in.pos = cmd.data() + done;
    in.n = std::min(chunk, cmd.size() - done);
    mc::Trace tr;
    tr.error = err.data() + done;
    axis.run(in, tr);
  }
  return err;
}

}  // namespace

TEST(ThreadStress, TwoThreadsRunningOneCardLoseNoTicks) {
  mc::Card card(4, tuned_axis());
  card.axis_on(0);
  t_move(card, 0, 20000, 4, 0.05);
  constexpr std::size_t kPerThread = 20000;
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t) threads.emplace_back([&] { locked_card_run(card, kPerThread, 997); });
  for (auto& th : threads) th.join();
  EXPECT_EQ(card.tick(), static_cast<long long>(2 * kPerThread));
}

TEST(ThreadStress, SamplerReadWhileTheCardRuns) {
  mc::Card card(4, tuned_axis());
  card.axis_on(1);
  t_move(card, 1, 30000, 6, 0.1);
  mc::SamplerConfig cfg;
  mc::SampleChannel c;
  c.axis = 1;
  c.signal = mc::SampleSignal::error;
  cfg.channels = {c};
  cfg.depth = 64;
  cfg.continuous = true;
  {
    std::lock_guard<std::recursive_mutex> state(locks_of(&card)->state);
    card.scope().start_sampler(cfg);
  }
  std::atomic<bool> done{false};
  std::size_t popped = 0;
  std::thread runner([&] {
    locked_card_run(card, 40000, 500);
    done = true;
  });
  std::thread reader([&] {
    int restarts = 0;
    while (!done) {
      std::lock_guard<std::recursive_mutex> state(locks_of(&card)->state);
      auto& s = card.scope().sampler();
      if (s.block_ready()) {
        const mc::SampleBlock b = s.pop_block();
        EXPECT_EQ(b.ticks.size(), 64u);
        ++popped;
      } else {
        (void)s.snapshot();
      }
      if (++restarts % 200 == 0) {  // stop and start again, as a host program may
        s.stop();
        card.scope().start_sampler(cfg);
      }
    }
  });
  runner.join();
  reader.join();
  EXPECT_EQ(card.tick(), 40000);
  EXPECT_GT(popped, 0u);
}

TEST(ThreadStress, ThreadsByObjectsByOperationsMatchTheSerialRuns) {
  // 4 threads x 3 axes x (run, state read, servo on) x 300 iterations: every axis's runs match the serial runs.
  constexpr int kAxes = 3, kThreads = 4, kIterations = 300;
  std::vector<double> cmd(400);
  for (std::size_t k = 0; k < cmd.size(); ++k) cmd[k] = 5.0 * static_cast<double>(k);
  mc::Axis reference(tuned_axis());
  const std::vector<double> expected = locked_axis_run(reference, cmd, 400);
  std::vector<mc::Axis> axes;
  for (int a = 0; a < kAxes; ++a) axes.emplace_back(tuned_axis());
  std::atomic<int> mismatches{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int it = 0; it < kIterations; ++it) {
        mc::Axis& axis = axes[static_cast<std::size_t>((t + it) % kAxes)];
        auto locks = locks_of(&axis);
        switch ((t + it) % 3) {
          case 0: {  // a whole run from power-on: reset and run under the run lock, like a user's two calls
            std::lock_guard<std::recursive_mutex> run(locks->run);
            {
              std::lock_guard<std::recursive_mutex> state(locks->state);
              axis.reset(0.0);
            }
            if (locked_axis_run(axis, cmd, 37) != expected) ++mismatches;
            break;
          }
          case 1: {
            std::lock_guard<std::recursive_mutex> state(locks->state);
            if (!std::isfinite(axis.feedback_pulse()) || !std::isfinite(axis.speed_rad_s())) ++mismatches;
            break;
          }
          default: {
            std::lock_guard<std::recursive_mutex> state(locks->state);
            axis.set_servo_on(true);
            break;
          }
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(ThreadStress, SeparateObjectsShareNothing) {
  // Independent cards in parallel threads give the serial result: no hidden shared state in the core.
  auto one = [] {
    mc::Card c(4, tuned_axis());
    c.axis_on(2);
    t_move(c, 2, 5000, 3, 0.05);
    c.run(6000);
    return c.actual_pos(2);
  };
  const double serial = one();
  std::vector<double> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t) threads.emplace_back([&, t] { got[t] = one(); });
  for (auto& th : threads) th.join();
  for (double g : got) EXPECT_EQ(g, serial);
}

// Decision FV28: a batch's workers share only the block counter, the done counter and the stop flag; with a poll
// that watches them, every thread count gives the one-thread metrics bit for bit, and a poll that says stop ends the
// batch with BatchStopped, leaving the rows never started as they were.
TEST(ThreadStress, BatchWorkersAndTheirPollShareOnlyTheCounters) {
  mc::AxisConfig base;
  base.servo_period_s = 250e-6;
  std::vector<double> cmd(600, 1000.0);
  for (std::size_t k = 0; k < 20; ++k) cmd[k] = 0.0;
  const std::size_t plants = 300;
  std::vector<double> inertia(plants);
  for (std::size_t i = 0; i < plants; ++i) inertia[i] = 8e-5 + 1e-7 * static_cast<double>(i);
  mc::BatchInput in;
  in.base = base;
  in.parameter_names = {"plant.inertia_kgm2"};
  in.parameters = inertia.data();
  in.plants = plants;
  in.pos = cmd.data();
  in.n = cmd.size();
  auto run = [&](int threads, std::function<bool(std::size_t, std::size_t)> poll) {
    std::vector<mc::MoveMetricsRow> rows(plants, mc::MoveMetricsRow{-1, -1, -1, -1, -1, -1});
    mc::BatchOutput out;
    out.metrics = rows.data();
    mc::BatchOptions opt;
    opt.threads = threads;
    opt.poll = std::move(poll);
    opt.poll_seconds = 0.001;
    mc::run_batch(in, out, opt);
    return rows;
  };
  const std::vector<mc::MoveMetricsRow> one = run(1, {});
  for (int threads : {2, 3, 4}) {
    std::size_t last = 0, calls = 0;
    const auto rows = run(threads, [&](std::size_t done, std::size_t total) {
      EXPECT_EQ(total, plants);
      EXPECT_GE(done, last);
      last = done;
      ++calls;
      return true;
    });
    EXPECT_EQ(last, plants);
    EXPECT_GE(calls, 1u);
    EXPECT_EQ(0, std::memcmp(rows.data(), one.data(), plants * sizeof(mc::MoveMetricsRow))) << threads;
  }
  std::vector<double> long_cmd(20000, 1000.0);  // ~0.25 ms a plant: the first poll (1 ms) comes mid-batch
  for (std::size_t k = 0; k < 20; ++k) long_cmd[k] = 0.0;
  in.pos = long_cmd.data();
  in.n = long_cmd.size();
  std::vector<mc::MoveMetricsRow> rows(plants, mc::MoveMetricsRow{-1, -1, -1, -1, -1, -1});
  mc::BatchOutput out;
  out.metrics = rows.data();
  mc::BatchOptions opt;
  opt.threads = 2;
  opt.poll_seconds = 0.001;
  opt.poll = [](std::size_t, std::size_t) { return false; };
  EXPECT_THROW(mc::run_batch(in, out, opt), mc::BatchStopped);
  std::size_t untouched = 0;
  for (const auto& r : rows) untouched += r.rise_time_s == -1.0 ? 1 : 0;
  EXPECT_GT(untouched, 0u);  // the first poll comes after 1 ms: most of the 300 plants were never started
}
