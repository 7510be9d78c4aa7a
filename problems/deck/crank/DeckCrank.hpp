// A `crank-slider` analysis as read from a deck: the mechanism of problems/scenes/README.md
// section 3 (one or several cranks on one shaft, each driving its slider), its masses and its
// pump, and the lambda values of the harmonic table. Nothing here runs.
#pragma once

#include <optional>
#include <vector>

#include "problems/scenes/CrankSlider.hpp"

namespace beamrotor {

struct DeckCrankSlider {
  crank::Geometry geometry;    ///< r, l (m)
  double speed = 0;            ///< crank speed (rad/s)
  std::vector<double> phases;  ///< each crank's angle ahead of the first (rad); first is 0
  int steps = 360;             ///< samples per revolution in the tables and charts
  std::optional<crank::DriveMasses> masses;  ///< without them no inertia loads
  double plungerDiameter = 0;                ///< m; 0: no delivery
  std::vector<double> lambdas;               ///< the harmonic table's lambda values (ascending)
};

}  // namespace beamrotor
