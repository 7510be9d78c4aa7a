// The torsion analysis' row in the table of analysis kinds (problems/deck/AnalysisKinds.hpp):
// the natural frequencies and shapes of the deck's shaft line in twist alone, with the
// shafts' polar inertia and the masses' Jp, whatever the deck's dimension.
#pragma once

#include "problems/deck/AnalysisRow.hpp"

namespace beamrotor {

struct TorsionSpec {
  static constexpr std::string_view deckType = "torsion";
  static constexpr std::array answers{Quantity::Kind::frequency};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
  int modes = 6;
  /// The eigenvalue omega^2 the modes are sought nearest (rad^2/s^2). A train no support
  /// holds in twist turns freely (a mode at 0 Hz), so there its reader puts a negative one
  /// unless the deck gives one (ReadTorsion.cpp).
  double shift = 0;
  bool shiftGiven = false;
};

}  // namespace beamrotor
