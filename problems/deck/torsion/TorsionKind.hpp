// The torsion analysis' row in the table of analysis kinds (problems/deck/AnalysisKinds.hpp):
// the natural frequencies and shapes in twist alone of the deck's drive train (`train:`,
// DeckReader) or, without one, of its shaft line (with the shafts' polar inertia and the
// masses' Jp, whatever the deck's dimension); and for a train, its interference diagram
// against excitation orders over a speed range and its steady response to harmonic torques.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "meshes/TrainBuilder.hpp"
#include "problems/deck/AnalysisRow.hpp"

namespace beamrotor {

/// A torque on a station varying as amplitude cos(order phi + phase), phi the angle its own
/// shaft has turned.
struct HarmonicTorque {
  TrainStation at;
  double order = 1;
  double amplitude = 0;  ///< N m
  double phase = 0;      ///< rad
  std::string source;    ///< "" as written, or the crank-slider analysis it comes from
};

/// The speeds of an interference diagram and response sweep (rad/s of the reference shaft).
struct TorsionSpeeds {
  double from = 0, to = 0;
  int steps = 100;
};

struct TorsionSpec {
  static constexpr std::string_view deckType = "torsion";
  static constexpr std::array answers{Quantity::Kind::frequency, Quantity::Kind::torsion};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
  /// A train deck needs no line of beams (readLine); one without a train is refused by read.
  static bool modelFree(const Field&) { return true; }
  int modes = 6;
  /// The eigenvalue omega^2 the modes are sought nearest (rad^2/s^2). A train no support
  /// holds in twist turns freely (a mode at 0 Hz), so there its reader puts a negative one
  /// unless the deck gives one (ReadTorsion.cpp).
  double shift = 0;
  bool shiftGiven = false;
  // A train's (`train:`) excitation; empty for a shaft line.
  int reference = 0;  ///< the shaft (index in the train) whose speed the fields below give
  double speed = 0;   ///< operating speed (rad/s) of the reference shaft; 0: none given
  std::optional<TorsionSpeeds> speeds;
  std::vector<double> orders;  ///< of the reference shaft's speed, for the interference diagram
  std::vector<HarmonicTorque> torques;
};

}  // namespace beamrotor
