// The shooting-segment cost with exact derivatives by forward sensitivity, in plain doubles (private to
// identify/; decisions FU1, rigid, and FV1, two-mass). It simulates what simulate_segment<M> simulates -- the
// zero-order-hold step, the logged command, the known current loop's torque, the constant load and the implicit
// dry-friction sub-step of plant/dry_friction.hpp (one body and one sweep, or two bodies and three Gauss-Seidel
// sweeps) -- and carries alongside the mechanical state x its sensitivity S = dx / d[p, x0] (rigid at most 2 x 8: six
// internal parameters, then the segment's two start states; two-mass at most 4 x 15: eleven parameters, four
// states; a parameter the solve holds has no lane, decision FV2):
//
//   free motion   xf = Phi x + Gamma [u, 0, -load, lag],    dxf = Phi S + (dPhi/dp) x + (dGamma/dp) [..] + Gamma d[..]
//   friction      f_b (the branch the values choose, each sweep seeing the other body's latest force), df_b from
//                 the branch's own formula
//   end           x' = xf + sum_b Gamma_b f_b  (a stick sets the body's speed and its row of S to 0; bodies held by
//                 stiction use Phi, Gamma of the discretisation with them locked)
//
// with dPhi/dp, dGamma/dp of the linear parameters (rigid: inertia, viscous; two-mass: both inertias, the shaft's
// stiffness and damping, both viscous frictions) from Van Loan's block exponential (the DiscretisationCache).
// Branches compare values only and the one-sided derivatives follow Ceres' Jet rules (|a|' = copysign(1, a) a',
// pow(r, e)' = e r^(e-1) r'), so the Jacobian is the AutoDiff one's (SegmentCost on Jets) to rounding:
// tests/cpp/test_segment_sensitivity.cpp checks it to 1e-12 relative on random states and parameters. A sub-step
// costs a few hundred multiply-adds on 8 or 15 lanes, where the Jets carried every operation, the constant
// discretisation's entries included, on all of them. An evaluation without a Jacobian (Ceres' trial steps) runs the
// same simulation without lanes (decision FV6).
#pragma once

#include <vector>

#include <ceres/ceres.h>

#include "shooting_model.hpp"

namespace servobench::identify::detail {

// The cost of the segment [start, start + count) of ctx's model (rigid or two-mass): residuals (measured -
// simulated) / measurement_scale, with the Jacobian with respect to the model's internal parameters and the
// segment's start states. `free`: the parameters the solve moves (the other parameters' Jacobian columns are 0, as
// FreeSegmentCost's); empty: every one. base (nullptr, or the whole internal parameter vector, read at every
// evaluation): parameter block 0 is then the free parameters alone, in `free`'s order, the held ones read from base,
// and the Jacobian has their columns only (decision FV4).
ceres::CostFunction* sensitivity_cost(const FitContext* ctx, int start, int count, std::vector<int> free,
                                      const double* base = nullptr);

}  // namespace servobench::identify::detail
