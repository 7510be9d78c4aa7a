// The summary's lines on the most stressed section: largest normal and shear stress of a static
// solution with their place (x, and the deck's segment), and over a sweep also the value of the
// swept parameter where they occur.
#pragma once

#include <ostream>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// "  largest normal stress 49.9 MPa at x = 0.575 m (rod)" and the shear stress line, from a
/// solution's element peaks (elementPeaks), each line led by `indent`; a largest stress at or
/// below `floor` (round-off: a truss's shear) is printed as 0 without a place.
void printStressPeaks(std::ostream& out, const Deck& deck, const Model& model,
                      const std::vector<ElementPeaks>& peaks, const NoiseFloor& floor,
                      const std::string& indent = "  ", const OutputUnits& units = {});

/// The same over every run of a sweep (first static analysis of each), with "at eta = 0.4".
void printSweepStressPeaks(std::ostream& out, const Deck& deck, const SweepResult& sweep,
                           const OutputUnits& units = {});

}  // namespace beamrotor::cli
