// Home and limit switches along the load's travel, in load angle (rad).
//
//   home switch on  while home_min_rad <= angle <= home_max_rad      (both inf: no home switch)
//   positive limit on while angle >= pos_limit_rad                    (inf: none)
//   negative limit on while angle <= neg_limit_rad                    (-inf: none)
//
// The plant speaks SI: convert from pulses with the encoder's counts_per_rev (2*pi rad per revolution).
// Polarity (normally open/closed) and enables are the controller's business (the card's LmtSns etc.).
#pragma once

#include <limits>

namespace servobench::plant {

struct SwitchParams {
  double home_min_rad = std::numeric_limits<double>::infinity();
  double home_max_rad = std::numeric_limits<double>::infinity();
  double pos_limit_rad = std::numeric_limits<double>::infinity();
  double neg_limit_rad = -std::numeric_limits<double>::infinity();
  void validate() const;
  bool home(double angle) const { return angle >= home_min_rad && angle <= home_max_rad; }
  bool pos_limit(double angle) const { return angle >= pos_limit_rad; }
  bool neg_limit(double angle) const { return angle <= neg_limit_rad; }
};

}  // namespace servobench::plant
