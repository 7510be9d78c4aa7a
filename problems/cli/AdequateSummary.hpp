// The summary's lines for a deck with `accuracy:`: the model chosen, its estimated error and
// its cost against the deck's own mesh.
#pragma once

#include <ostream>

#include "problems/run/AdequateChoice.hpp"

namespace beamrotor::cli {

void printAdequateChoice(std::ostream& out, const AdequateChoice& choice);

}  // namespace beamrotor::cli
