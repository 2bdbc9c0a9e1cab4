// The terms of one servo-law evaluation, in DAC counts (the card's controller units).
//
// Both laws report the same record every tick, like the ADLINK card's sampled PID_*_CALC signals
// (adlink.md §8): the proportional, integral, derivative, velocity and acceleration feed-forward and bias
// terms, and `total`, the law output after the law's own clamp (GT: ±MtrLmt). Without a clamp,
// total == p + i + d + vff + aff + bias. `vel` and `acc` are the feed-forward inputs the law used (GT: the
// profile's; APS: the command differences).
#pragma once

namespace servobench::control {

struct LawTerms {
  double p = 0.0;     // proportional term, counts
  double i = 0.0;     // integral term, counts
  double d = 0.0;     // derivative term, counts
  double vff = 0.0;   // velocity feed-forward term, counts
  double aff = 0.0;   // acceleration feed-forward term, counts
  double bias = 0.0;  // constant bias term (GT MtrBias), counts
  double total = 0.0; // law output after the law's clamp, counts
  double vel = 0.0;   // the command velocity the law used, pulse/tick
  double acc = 0.0;   // the command acceleration the law used, pulse/tick^2
};

}  // namespace servobench::control
