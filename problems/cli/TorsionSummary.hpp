// The lines `beamrotor solve` prints for a torsion analysis of a train beyond its modes: the
// shafts' speeds, where the orders cross the natural frequencies, and the vibratory torques
// and twists at the operating speed.
#pragma once

#include <ostream>

#include "problems/run/TorsionOutcome.hpp"

namespace beamrotor::cli {

void printTrain(std::ostream& out, const TorsionOutcome& t);

}  // namespace beamrotor::cli
