// The GUC-ECAT motion program's card module (vendor/googol/guc_program.hpp; GUC seed 002 Chapter 5, L2100-2560;
// decisions GS13-GS14, GY1-): the thread state machine (bind, run, pause, resume, stop, end, raise), the scheduling
// the host follows (thread order, start arguments), the data pages and globals with their checks and codes.
#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/guc_program.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;
using vg::GucCode;
using vg::GucStepEnd;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The test program of tests/python/test_gts_motion_program.py: mover(axis, target), waiter(n) with a local k,
// add(begin, end=100) with a default; globals count, flag, done.
void load(vg::GucProgram& p) {
  p.load({vg::GucFunction{"mover", {"axis", "target", "rtn", "sts"}, {false, false}, 7},
          vg::GucFunction{"waiter", {"n", "k"}, {false}, 22},
          vg::GucFunction{"add", {"begin", "end", "i"}, {false, true}, 33}},
         {"count", "flag", "done"}, {0, 0, 0});
}

// One host tick: every thread the module names steps once, with `end` for all (stepped() names the next one).
std::vector<int> tick(vg::GucProgram& p, GucStepEnd end = GucStepEnd::Yielded) {
  std::vector<int> stepped;
  for (auto s = p.next_step(-1); s; s = p.stepped(s->thread, end, 0.0, 0, {})) stepped.push_back(s->thread);
  return stepped;
}
}  // namespace

TEST(GucProgram, IsACardModuleCreatedOnFirstUseAndNotActiveInTheTick) {
  mc::Card card(8, servobench::test::tuned_axis());
  EXPECT_EQ(card.module_if_any<vg::GucProgram>(), nullptr);
  vg::GucProgram& p = vg::guc_program(card);
  EXPECT_EQ(&p, &vg::guc_program(card));
  EXPECT_FALSE(p.active());  // the card's tick skips it: the host steps the threads after the tick
  EXPECT_FALSE(p.loaded());
}

TEST(GucProgram, SymbolsGucL2150To2166) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  EXPECT_EQ(p.fun_id("mover").first, GucCode::CommandError);  // nothing downloaded
  EXPECT_EQ(p.var_id("", "count").first, GucCode::CommandError);
  load(p);
  EXPECT_EQ(p.fun_id("waiter"), std::make_pair(GucCode::Success, 2));
  EXPECT_EQ(p.fun_id("nope").first, GucCode::CommandError);
  const auto [c, v] = p.var_id("", "done");
  EXPECT_EQ(c, GucCode::Success);
  EXPECT_EQ(v.id, 2);
  EXPECT_EQ(v.function, "");
  EXPECT_EQ(p.var_id("mover", "target").second.id, 1);
  EXPECT_EQ(p.var_id("mover", "count").first, GucCode::CommandError);  // a global is not mover's
  EXPECT_EQ(p.var_id("nope", "x").first, GucCode::CommandError);
}

TEST(GucProgram, BindChecksAndRefusalsGucL2170To2175L2256L2258) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  EXPECT_EQ(p.bind(0, 1, 0), GucCode::CommandError);  // no program: no function 1
  load(p);
  for (double bad : {-1.0, 32.0, 0.5, kNaN}) {
    EXPECT_EQ(p.bind(bad, 1, 0), GucCode::ParameterError);
    EXPECT_EQ(p.bind(0, 1, bad), GucCode::ParameterError);
  }
  EXPECT_EQ(p.bind(0, 0, 0), GucCode::ParameterError);
  EXPECT_EQ(p.bind(0, kNaN, 0), GucCode::ParameterError);
  EXPECT_EQ(p.bind(0, 4, 0), GucCode::CommandError);  // three functions
  EXPECT_EQ(p.bind(0, 1, 0), GucCode::Success);
  EXPECT_EQ(p.bind(1, 2, 0), GucCode::CommandError);  // page 0 is thread 0's
  EXPECT_EQ(p.bind(0, 2, 0), GucCode::Success);       // rebinding a thread that does not run
  EXPECT_EQ(p.run_thread(0), GucCode::Success);
  EXPECT_EQ(p.bind(0, 1, 0), GucCode::CommandError);  // not while it runs
  EXPECT_EQ(p.pause_thread(0), GucCode::Success);
  EXPECT_EQ(p.bind(0, 1, 0), GucCode::CommandError);  // nor while paused
  EXPECT_EQ(p.stop_thread(0), GucCode::Success);
  EXPECT_EQ(p.bind(0, 1, 0), GucCode::Success);
}

TEST(GucProgram, ThreadStateMachineGucL2178To2213) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  load(p);
  EXPECT_EQ(p.run_thread(2), GucCode::CommandError);  // unbound
  ASSERT_EQ(p.bind(2, 2, 5), GucCode::Success);
  ASSERT_EQ(p.bind(1, 3, 4), GucCode::Success);
  EXPECT_EQ(p.pause_thread(2), GucCode::CommandError);  // does not run
  EXPECT_FALSE(p.any_active());
  ASSERT_EQ(p.run_thread(2), GucCode::Success);
  ASSERT_EQ(p.run_thread(1), GucCode::Success);
  EXPECT_EQ(p.run_thread(2), GucCode::CommandError);  // already running
  auto [c, s] = p.thread_status(2);
  EXPECT_EQ(c, GucCode::Success);
  EXPECT_EQ(s.run, 1);
  EXPECT_EQ(s.line, 22);  // the function's first line until it steps
  // the first step of each: in thread order, with the start flag once
  auto s1 = p.next_step(-1);
  ASSERT_TRUE(s1);
  EXPECT_EQ(s1->thread, 1);
  EXPECT_TRUE(s1->start);
  EXPECT_EQ(s1->fun_id, 3);
  auto s2 = p.stepped(1, GucStepEnd::Yielded, 0, 40, {});  // the next thread to step
  ASSERT_TRUE(s2);
  EXPECT_EQ(s2->thread, 2);
  EXPECT_TRUE(s2->start);
  p.record_error(7);  // a GT call of the current thread
  EXPECT_FALSE(p.stepped(2, GucStepEnd::Yielded, 0, 25, {}));  // the last this tick
  EXPECT_EQ(p.thread_status(2).second.error, 7);
  EXPECT_EQ(p.thread_status(2).second.line, 25);
  p.record_error(1);  // outside a step: nobody's
  EXPECT_EQ(p.thread_status(2).second.error, 7);
  EXPECT_EQ(tick(p), (std::vector<int>{1, 2}));
  EXPECT_FALSE(p.next_step(-1).value().start);  // started once
  p.stepped(1, GucStepEnd::Yielded, 0, 0, {});
  // pause: skipped, status 2; resume: stepped again where it stood
  ASSERT_EQ(p.pause_thread(1), GucCode::Success);
  EXPECT_EQ(p.pause_thread(1), GucCode::CommandError);
  EXPECT_EQ(p.thread_status(1).second.run, 2);
  EXPECT_TRUE(p.any_active());
  EXPECT_EQ(tick(p), std::vector<int>{2});
  ASSERT_EQ(p.run_thread(1), GucCode::Success);
  EXPECT_EQ(p.thread_status(1).second.run, 1);
  auto r = p.next_step(-1);
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->start);  // resumed, not restarted
  // ends: returned value -> run 0, result; raised -> run 0, error 1
  p.stepped(1, GucStepEnd::Returned, 5050, 0, {});
  EXPECT_EQ(p.thread_status(1).second.run, 0);
  EXPECT_DOUBLE_EQ(p.thread_status(1).second.result, 5050);
  EXPECT_EQ(p.thread_status(1).second.line, 40);
  EXPECT_EQ(tick(p, GucStepEnd::Raised), std::vector<int>{2});
  EXPECT_EQ(p.thread_status(2).second.run, 0);
  EXPECT_EQ(p.thread_status(2).second.error, 1);
  EXPECT_FALSE(p.any_active());
  EXPECT_TRUE(tick(p).empty());
  // a stopped thread starts again from the beginning, its status new
  ASSERT_EQ(p.run_thread(2), GucCode::Success);
  EXPECT_EQ(p.thread_status(2).second.error, 0);
  EXPECT_TRUE(p.next_step(-1).value().start);
  p.stepped(2, GucStepEnd::Yielded, 0, 0, {});
  EXPECT_EQ(p.stop_thread(2), GucCode::Success);
  EXPECT_EQ(p.stop_thread(2), GucCode::Success);  // any state
  EXPECT_EQ(p.thread_status(2).second.run, 0);
  for (double bad : {-1.0, 32.0, 1.5, kNaN}) {
    EXPECT_EQ(p.run_thread(bad), GucCode::ParameterError);
    EXPECT_EQ(p.stop_thread(bad), GucCode::ParameterError);
    EXPECT_EQ(p.pause_thread(bad), GucCode::ParameterError);
    EXPECT_EQ(p.thread_status(bad).first, GucCode::ParameterError);
  }
}

TEST(GucProgram, AStepThatStopsItsOwnThreadLeavesItStopped) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  load(p);
  ASSERT_EQ(p.bind(0, 2, 0), GucCode::Success);
  ASSERT_EQ(p.run_thread(0), GucCode::Success);
  ASSERT_TRUE(p.next_step(-1));
  EXPECT_EQ(p.stop_thread(0), GucCode::Success);  // GT_StopThread(0) from thread 0's own step
  p.stepped(0, GucStepEnd::Yielded, 0, 30, {});
  EXPECT_EQ(p.thread_status(0).second.run, 0);
  EXPECT_FALSE(p.any_active());
}

TEST(GucProgram, StartArgumentsFromThePageTakenAtRunThread) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  load(p);
  ASSERT_EQ(p.bind(3, 3, 7), GucCode::Success);  // add(begin, end=100)
  ASSERT_EQ(p.set_var_value(7, 0, "add", {51}, 1), GucCode::Success);
  ASSERT_EQ(p.run_thread(3), GucCode::Success);
  ASSERT_EQ(p.set_var_value(7, 0, "add", {1}, 1), GucCode::Success);  // after the start: not its argument
  auto s = p.next_step(-1);
  ASSERT_TRUE(s);
  // begin from the page; end unset with a default: not passed (the function's default)
  ASSERT_EQ(s->args.size(), 1u);
  EXPECT_EQ(s->args[0].first, "begin");
  EXPECT_DOUBLE_EQ(s->args[0].second, 51);
  p.stepped(3, GucStepEnd::Returned, 0, 0, {});
  // an unset parameter without a default starts at 0 (a C local nobody set)
  ASSERT_EQ(p.bind(4, 2, 8), GucCode::Success);
  ASSERT_EQ(p.run_thread(4), GucCode::Success);
  s = p.next_step(-1);
  ASSERT_TRUE(s);
  ASSERT_EQ(s->args.size(), 1u);
  EXPECT_EQ(s->args[0].first, "n");
  EXPECT_DOUBLE_EQ(s->args[0].second, 0);
}

TEST(GucProgram, VariablesGucL2215To2233) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {1}, 1), GucCode::CommandError);  // nothing downloaded
  load(p);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {7, 8, 9}, 3), GucCode::Success);
  EXPECT_EQ(p.var_value(-1, 0, "", 3).second, (std::vector<double>{7, 8, 9}));
  EXPECT_EQ(p.global_values(), (std::vector<double>{7, 8, 9}));
  // 7: page, count, a value not a DINT integer, fewer values than count
  EXPECT_EQ(p.set_var_value(32, 0, "", {1}, 1), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(-2, 0, "", {1}, 1), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(-1, 0, "", std::vector<double>(9, 1), 9), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {2147483648.0}, 1), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {-2147483648.0}, 1), GucCode::Success);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {0.5}, 1), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {kNaN}, 1), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(-1, 0, "", {1, 2}, 3), GucCode::ParameterError);
  EXPECT_EQ(p.set_var_value(kNaN, 0, "", {1}, 1), GucCode::ParameterError);
  // 1: past the last global, a local on page -1, a global on a data page, an id that is no index
  EXPECT_EQ(p.set_var_value(-1, 0, "", {1, 1, 1, 1}, 4), GucCode::CommandError);
  EXPECT_EQ(p.set_var_value(-1, 0, "mover", {1}, 1), GucCode::CommandError);
  EXPECT_EQ(p.set_var_value(0, 0, "", {1}, 1), GucCode::CommandError);
  EXPECT_EQ(p.set_var_value(-1, kNaN, "", {1}, 1), GucCode::CommandError);
  EXPECT_EQ(p.set_var_value(-1, -1, "", {1}, 1), GucCode::CommandError);
  EXPECT_EQ(p.var_value(-1, 0, "mover", 1).first, GucCode::CommandError);
  EXPECT_EQ(p.var_value(-1, 0, "", 9).first, GucCode::CommandError);  // a read's bad count: no such variables
  EXPECT_EQ(p.var_value(33, 0, "", 1).first, GucCode::ParameterError);
  // a data page: values set read back; never set reads 0
  EXPECT_EQ(p.set_var_value(5, 0, "waiter", {50}, 1), GucCode::Success);
  EXPECT_EQ(p.var_value(5, 0, "waiter", 2).second, (std::vector<double>{50, 0}));
  // a running thread's live locals (as the host reported them) over the page's values
  ASSERT_EQ(p.bind(1, 2, 5), GucCode::Success);
  ASSERT_EQ(p.run_thread(1), GucCode::Success);
  ASSERT_TRUE(p.next_step(-1));
  p.stepped(1, GucStepEnd::Yielded, 0, 24, {std::optional<double>(50), std::optional<double>(10)});
  EXPECT_EQ(p.var_value(5, 0, "waiter", 2).second, (std::vector<double>{50, 10}));
  ASSERT_EQ(p.pause_thread(1), GucCode::Success);
  EXPECT_EQ(p.var_value(5, 1, "waiter", 1).second, std::vector<double>{10});  // paused: where it stood
  ASSERT_EQ(p.stop_thread(1), GucCode::Success);
  EXPECT_EQ(p.var_value(5, 0, "waiter", 2).second, (std::vector<double>{50, 0}));  // stopped: the page again
}

TEST(GucProgram, DownloadAndResetStopTheThreads) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GucProgram& p = vg::guc_program(card);
  load(p);
  ASSERT_EQ(p.bind(0, 2, 0), GucCode::Success);
  ASSERT_EQ(p.set_var_value(0, 0, "waiter", {3}, 1), GucCode::Success);
  ASSERT_EQ(p.run_thread(0), GucCode::Success);
  card.reset();  // GT_Reset: the threads stop, the program and bindings stay (L2245)
  EXPECT_FALSE(p.any_active());
  EXPECT_EQ(p.thread_status(0).second.run, 0);
  EXPECT_EQ(p.fun_id("waiter").second, 2);
  EXPECT_EQ(p.run_thread(0), GucCode::Success);
  load(p);  // a new download: threads unbound, pages cleared, globals from the program
  EXPECT_FALSE(p.any_active());
  EXPECT_EQ(p.run_thread(0), GucCode::CommandError);
  EXPECT_EQ(p.var_value(0, 0, "waiter", 1).second, std::vector<double>{0});
  EXPECT_THROW(p.load({}, {"x"}, {}), std::invalid_argument);
  EXPECT_THROW(p.set_global_values({1}), std::invalid_argument);
  EXPECT_THROW(p.stepped(32, GucStepEnd::Yielded, 0, 0, {}), std::invalid_argument);
}
