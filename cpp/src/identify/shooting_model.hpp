// The output-error model of the time-domain fit (private to identify/): the context the shooting segments share,
// the model simulated over one segment (double or Ceres Jet: the AutoDiff cost of a segment) and the residual
// blocks of a multiple-shooting problem. time_fit.cpp solves; shooting_model.cpp builds and evaluates.
#pragma once

#include <memory>
#include <vector>

#include <ceres/ceres.h>

#include "servobench/identify/time_fit.hpp"

namespace servobench::identify::detail {

// Everything the segments share.
struct FitContext {
  ModelLayout layout;
  const TimeLog* log = nullptr;
  std::vector<double> lag;  // current-loop torque at every sample (parameter-free: the loop is known)
  double lag_decay = 0.0;   // exp(-wc h) over one sub-step h
  bool has_load = true;     // false: the constant load is held at 0 (no input column for it)
  int substeps = 1;
  int output_index = 0;
  double inv_scale = 1.0;
  double continuity_weight = 1.0;
  mutable std::unique_ptr<DiscretisationCache> cache;
};


// The layout, the output, the discretisation cache and the known current loop's torque at every sample.
void init_context(FitContext& ctx, const TimeLog& log, const TimeFitOptions& options);
// Simulates samples [start, start + count) from the mechanical state x0 (internal parameters p); out per sample.
void run_segment(const FitContext& ctx, const double* p, const double* x0, int start, int count, double* out);
// The mechanical state `steps` samples after `start`, simulated from x0 (internal parameters p) into x_end.
void state_at(const FitContext& ctx, const double* p, const double* x0, int start, int steps, double* x_end);
// The log's lengths, finiteness and minimum length for these options (std::invalid_argument naming the sample).
void check_log(const TimeLog& log, const TimeFitOptions& o);
// One residual block per segment (AutoDiff), linked to the next one with continuity_weight > 0; with_loss: the
// options' robust loss. held (one entry per parameter, or nullptr): the parameters the solve holds constant; an
// unlinked segment then differentiates along the free parameters only (FreeSegmentCost, the same derivatives), a
// with options.analytic_jacobian by forward sensitivity in doubles (segment_sensitivity.hpp).
// free_block (room for the parameters `held` leaves free, in order, filled with their values; or nullptr): when held
// is given and no segment is linked, the residual blocks take free_block as their parameter block and read the held
// values from p (which must then stay in place and unchanged through the solve), and the call returns true;
// otherwise p is the parameter block (the caller holds its constant entries with a SubsetManifold) and it returns
// false.
bool add_segment_blocks(ceres::Problem& problem, const FitContext& ctx, ShootingProblem& sp, double* p,
                        const TimeFitOptions& options, bool with_loss = true,
                        const std::vector<bool>* held = nullptr, double* free_block = nullptr);

}  // namespace servobench::identify::detail
