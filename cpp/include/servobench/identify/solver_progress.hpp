// A Ceres iteration callback that reports (iteration, cost) to a user function, which may stop the solve.
#pragma once

#include <functional>

#include <ceres/iteration_callback.h>

namespace servobench::identify {

class SolverProgress : public ceres::IterationCallback {
 public:
  explicit SolverProgress(const std::function<bool(int, double)>& f) : f_(f) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    return f_(s.iteration, s.cost) ? ceres::SOLVER_CONTINUE : ceres::SOLVER_TERMINATE_SUCCESSFULLY;
  }

 private:
  const std::function<bool(int, double)>& f_;
};

}  // namespace servobench::identify
