// The rigid model's shooting-segment cost with exact derivatives by forward sensitivity, in plain doubles (private
// to identify/; decision FU1). It simulates what simulate_segment<kRigid> simulates -- the zero-order-hold step,
// the logged command, the known current loop's torque, the constant load and the implicit dry-friction sub-step of
// plant/dry_friction.hpp (one body, one sweep) -- and carries alongside the state x = [angle, speed] its
// sensitivity S = dx / d[p, x0] (2 x 8: the six internal parameters, then the segment's start state):
//
//   free motion   xf = Phi x + Gamma [u, 0, -load, lag],    dxf = Phi S + (dPhi/dp) x + (dGamma/dp) [..] + Gamma d[..]
//   friction      f (the branch the values choose),          df from the branch's own formula
//   end           x' = xf + Gamma_f f  (a stick sets the speed and its row of S to 0; a locked body uses Phi, Gamma
//                 of the locked discretisation)
//
// with dPhi/dp, dGamma/dp of the linear parameters (inertia, viscous) from Van Loan's block exponential (the
// DiscretisationCache). Branches compare values only and the one-sided derivatives follow Ceres' Jet rules (|a|'
// = copysign(1, a) a', pow(r, e)' = e r^(e-1) r'), so the Jacobian is the AutoDiff one's (SegmentCost on Jets) to
// rounding: tests/cpp/test_rigid_sensitivity.cpp checks it to 1e-12 relative on random states and parameters.
// A sub-step costs a few dozen multiply-adds on 8 lanes, where the Jets carried every operation on 6 or 8.
#pragma once

#include <vector>

#include <ceres/ceres.h>

#include "shooting_model.hpp"

namespace servobench::identify::detail {

// The cost of the rigid segment [start, start + count): residuals (measured - simulated) / measurement_scale, with
// the Jacobian with respect to the 6 internal parameters and the segment's 2 start states. `free`: the parameters
// the solve moves (the other parameters' Jacobian columns are 0, as FreeSegmentCost's); empty: every one.
ceres::CostFunction* rigid_sensitivity_cost(const FitContext* ctx, int start, int count, std::vector<int> free);

}  // namespace servobench::identify::detail
