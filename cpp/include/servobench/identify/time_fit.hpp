// Time-domain grey-box identification of the plant from a log, solved with Ceres.
//
// The log holds, per sample k (period Ts): the torque command held over [t_k, t_k+1) and the measured position (or
// speed) at t_k. The model is the simulator's own plant (identify/plant_model.hpp: the same matrices, the same exact
// zero-order hold, the same implicit dry-friction sub-step), driven through the known current loop. The fit is an
// output-error fit by multiple shooting: the stretches of one-way motion (rest phases and reversals left out, so
// that no segment is simulated through a stick-slip event) are cut into segments of about `segment_samples`; each
// segment starts from
// its own free initial mechanical state (nuisance parameters) and is simulated from the logged torque; the residual
// is the measured minus the simulated output, divided by `measurement_scale`. Short segments keep the problem
// well-conditioned (an open-loop simulation of an integrating plant drifts) and the initial states absorb the
// quantisation offset. Derivatives: by forward sensitivity in doubles through the sub-step (segment_sensitivity.cpp,
// the default analytic_jacobian; its residual-only evaluations run the same code without derivative lanes, equal to
// the simulator's doubles to rounding), or by Ceres automatic differentiation (Jets) of the same code (linked
// segments, analytic_jacobian false); the discretisation's derivatives by Van Loan's block exponential.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "servobench/identify/fit_report.hpp"
#include "servobench/identify/plant_model.hpp"

namespace servobench::identify {

struct TimeLog {
  double sample_period_s = 0.0;   // Ts, s (> 0)
  std::vector<double> torque_nm;  // torque command held over [t_k, t_k+1), N*m
  std::vector<double> measured;   // position (rad) or speed (rad/s) at t_k
  bool measured_is_speed = false; // measured holds speeds
  bool measured_on_load = false;  // measured on the load side (two-mass; the same body when rigid)
};

enum class Loss { kNone = 0, kHuber = 1, kSoftLOne = 2, kCauchy = 3 };

struct TimeFitOptions {
  PlantModel model = PlantModel::kRigid;
  int segment_samples = 1000;       // samples per shooting segment (about) in the final stage, 10..100000
  // The continuation starts with segments of this length and doubles it up to segment_samples, each stage from
  // the previous one's parameters: short segments have a wide basin of attraction, long ones small errors.
  int initial_segment_samples = 250;  // 10..100000
  // Segmentation into one-way motion (see shooting_segments in shooting_model.cpp): the direction is the sign of the
  // measured change over direction_window samples when it is at least rest_threshold (in measurement_scale units);
  // edge_samples are trimmed at both ends of every run; runs shorter than min_segment_samples are not used.
  int min_segment_samples = 20;     // 3..segment_samples
  int edge_samples = 3;             // 0..1000
  int direction_window = 6;         // 2..1000
  double rest_threshold = 2.0;      // >= 0
  int substeps = 1;                 // plant sub-steps per sample (the simulator's Axis substeps), 1..1000
  double current_bw_hz = std::numeric_limits<double>::infinity();  // known current-loop bandwidth, Hz (inf: none)
  double stribeck_exponent = 2.0;   // known Stribeck exponent, 0.5..4
  double measurement_scale = 1.0;   // residual unit (e.g. one encoder count in rad), > 0
  // Weight of the multiple-shooting continuity residuals (each segment's simulated end state minus the next
  // segment's start, angles in measurement_scale units, speeds in measurement_scale per sample); 0: independent
  // segments. Continuity carries each segment's state through stick-slip events that would otherwise trap it.
  double continuity_weight = 0.0;
  Loss loss = Loss::kNone;          // robust loss on the scaled residuals
  double loss_scale = 3.0;          // where the robust loss departs from least squares, in measurement_scale units
  // With the Stribeck peak free, a first stage holds its level and speed at their guesses (see fit_time_domain).
  bool hold_stribeck_first = true;
  // The segments' Jacobian by forward sensitivity in doubles (exact; Ceres' AutoDiff to rounding, decisions FU1
  // and FV1); false: automatic differentiation on Jets. Linked segments use AutoDiff.
  bool analytic_jacobian = true;
  int max_iterations = 200;         // 1..10000
  int num_threads = 1;              // 1..64
  double max_relative_std_error = 0.2;  // a free parameter less certain than this is reported not identifiable
  // Called after every iteration with (iteration, cost); return false to stop the solve.
  std::function<bool(int, double)> progress;
  void validate() const;

  // The option table (decision OP3, OQ2): the one place the Python API (fit_time, oefit) reads each option's default,
  // unit and doc from. The model and the loss are chosen by name in Python; the progress callback is not an option.
  // Python's fit_time sets measurement_scale to one encoder count, so the "scale" unit reads "counts" there.
  template <class V>
  static void describe(V&& v) {
    using O = TimeFitOptions;
    v("segment_samples", &O::segment_samples, "samples", "multiple-shooting segment length (about) of the final stage, 10..100000");
    v("initial_segment_samples", &O::initial_segment_samples, "samples", "segment length of the first stage of the continuation (doubled up to segment_samples, each stage from the previous one's parameters: short segments have a wide basin of attraction, long ones small errors), 10..100000");
    v("min_segment_samples", &O::min_segment_samples, "samples", "runs of one-way motion shorter than this are not fitted, 3..segment_samples");
    v("edge_samples", &O::edge_samples, "samples", "trimmed at both ends of every run of one-way motion, 0..1000");
    v("direction_window", &O::direction_window, "samples", "the direction of motion is the sign of the measured change over this many samples, 2..1000");
    v("rest_threshold", &O::rest_threshold, "scale", "a measured change over direction_window below this is rest, >= 0 (rest phases and reversals are not fitted: a segment simulated through a stick-slip event can trap the solver)");
    v("substeps", &O::substeps, "", "plant sub-steps per sample (the simulator's Axis substeps), 1..1000");
    v("current_bw_hz", &O::current_bw_hz, "Hz", "the known current-loop bandwidth, > 0 (inf: none)");
    v("stribeck_exponent", &O::stribeck_exponent, "", "the known Stribeck exponent, 0.5..4");
    v("measurement_scale", &O::measurement_scale, "", "the residual's unit in the measured signal's units (e.g. one encoder count in rad), > 0");
    v("continuity_weight", &O::continuity_weight, "", "weight of the multiple-shooting continuity residuals, >= 0; 0: independent segments");
    v("loss_scale", &O::loss_scale, "scale", "where the robust loss departs from least squares, > 0");
    v("hold_stribeck_first", &O::hold_stribeck_first, "", "with the Stribeck peak free, solve a first stage with its level and speed held at their guesses (far from the truth the peak otherwise tends to vanish, ws -> 0, and stay vanished)");
    v("analytic_jacobian", &O::analytic_jacobian, "", "the shooting segments' Jacobian by forward sensitivity in plain doubles (exact: the automatic differentiation's to rounding, 1e-12 relative; rigid and two-mass, decisions FU1, FV1); false: Ceres' automatic differentiation on Jets. Linked segments (continuity_weight > 0) always use automatic differentiation");
    v("max_iterations", &O::max_iterations, "", "solver iterations per stage at most, 1..10000");
    v("num_threads", &O::num_threads, "",
      "Ceres threads inside one fit, 1..64; 1 (default) is deterministic (bit-identical estimates). More threads "
      "evaluate the segments in parallel (the Jacobian is about 90 % of a solve, the report's Stages line) but do "
      "not lower CPU time (5 s bench experiment, rigid A, one start, automatic differentiation before FU1: 0.30-0.34 s "
      "CPU with 2 threads against 0.30-0.32 s with 1 at load 13 on 2 cores, decision FT6; wall time 0.94x with 2 threads idle, issue 22); "
      "with more than one, Ceres sums the Schur complement in a varying order (estimates differ at ~1e-8)");
    v("max_relative_std_error", &O::max_relative_std_error, "", "a free parameter whose standard error exceeds this fraction of its own value is not identifiable, > 0");
  }
};

// The starting point: one entry per model parameter (model_parameters order).
struct ParameterSetup {
  std::vector<double> initial;
  std::vector<bool> fixed;     // held at initial (empty: none fixed)
  std::vector<double> lower;   // empty: the physical bounds of model_parameters
  std::vector<double> upper;   // empty: +inf
};

struct TimeFitResult {
  std::vector<ParameterEstimate> parameters;
  FitSummary summary;
  std::vector<double> predicted;  // the model's output per sample (each segment from its fitted start), unit of measured
  std::vector<double> residual;   // measured - predicted
  std::vector<int> segment_start; // first sample of each segment
  std::vector<int> segment_count; // its length; samples outside every segment have NaN predicted/residual
  std::vector<double> segment_states;  // the fitted start state of every segment, concatenated (state_size each)
  // The parameters (model_parameters order, SI) at the end of every stage of the continuation that ran.
  std::vector<std::vector<double>> stage_parameters;
  // >= 0: the fit stopped after this stage because its parameters agreed with another start's at the same stage
  // (StageJoin); only stage_parameters and the summary's iterations, seconds and report are then filled.
  int joined_stage = -1;
};

// Another start's parameters at the end of each stage (TimeFitResult::stage_parameters of a fit of the same log with
// the same options): a fit whose parameters at the end of stage k (not the last) agree with points[k] -- every free
// parameter within rtol of its value, relative, or both within 1e-300 -- stops there, since from the same point the
// remaining stages repeat that start's (decision FV15).
struct StageJoin {
  std::vector<std::vector<double>> points;
  double rtol = 1e-4;
};

// Fits the plant. Throws std::invalid_argument for bad input (lengths, non-finite values, a log shorter than two
// segments, bounds not around the initial values).
TimeFitResult fit_time_domain(const TimeLog& log, const ParameterSetup& setup, const TimeFitOptions& options,
                              const StageJoin* join = nullptr);

// One stage's multiple-shooting problem laid out for an outside least-squares solver (the benchmark against SciPy
// solves exactly what Ceres solves): the segments of about options.segment_samples, their start states from the
// data (a line through each segment's first samples), and the residual with its Jacobian.
struct ShootingProblem {
  std::vector<int> starts, counts;  // first sample and length of every segment
  std::vector<double> states;       // initial mechanical state of every segment, concatenated (state_size each)
  int state_size = 0;
};
ShootingProblem shooting_problem(const TimeLog& log, const TimeFitOptions& options);

struct SparseJacobian {  // compressed rows
  int rows = 0, cols = 0;
  std::vector<int> row_ptr, col_index;
  std::vector<double> values;
};

// The residual vector (measured - simulated, over measurement_scale; no loss applied) at the INTERNAL parameter
// vector p (the breakaway entry holds the Stribeck excess Fs - Fc, see plant_model.hpp) and the segment states;
// with jacobian != nullptr also d residual / d [p, states] by the fit's automatic differentiation.
std::vector<double> shooting_residual(const TimeLog& log, const TimeFitOptions& options,
                                      const ShootingProblem& problem, const std::vector<double>& p,
                                      const std::vector<double>& states, SparseJacobian* jacobian);

// Simulates the model from one initial mechanical state over a whole log (no shooting), for checks and plots:
// the same code the fit differentiates, on double. Returns the output per sample.
std::vector<double> simulate_model(const TimeLog& log, const std::vector<double>& parameters,
                                   const std::vector<double>& initial_state, const TimeFitOptions& options);

}  // namespace servobench::identify
