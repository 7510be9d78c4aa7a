// The rows of the table of analysis kinds (problems/deck/AnalysisKinds.hpp) that solve the
// beams and frames as they are: statics (second_order: true included), modes (prestressed:
// true included), buckling, a train of loads moving along a path (influence lines and
// their envelopes) and the peak response to a ground acceleration's spectrum. Each row states
// its deck type, its reader, the check quantities it answers and holds the settings its entry
// gives.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fem/modal/BaseMotion.hpp"
#include "fem/modal/ResponseSpectrum.hpp"
#include "problems/deck/AnalysisRow.hpp"
#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

struct StaticSpec {
  static constexpr std::string_view deckType = "static";
  static constexpr std::array answers{
      Quantity::Kind::reaction,    Quantity::Kind::displacement,    Quantity::Kind::maxStress,
      Quantity::Kind::maxShear,    Quantity::Kind::maxMoment,       Quantity::Kind::maxDisplacement,
      Quantity::Kind::memberForce, Quantity::Kind::memberDeflection, Quantity::Kind::sectionProperty,
      Quantity::Kind::resultantAt};
  static constexpr bool needsMass = false;
  void read(const reader::Context& c, const Field& f);
  bool secondOrder = false;  ///< equilibrium in the deformed state (fem/stability)
  /// `accept_round_off: true`: keep a solution whose measured round-off leaves no digit to
  /// trust (problems/run/UntrustedStatics.hpp), which otherwise fails the analysis.
  bool acceptRoundOff = false;
};

struct ModalSpec {
  static constexpr std::string_view deckType = "modal";
  static constexpr std::array answers{Quantity::Kind::frequency, Quantity::Kind::sectionProperty};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
  int modes = 6;
  double shift = 0;          ///< the eigenvalue omega^2 the modes are sought nearest (rad^2/s^2)
  bool prestressed = false;  ///< about the state the deck's loads put the structure in
};

struct BucklingSpec {
  static constexpr std::string_view deckType = "buckling";
  static constexpr std::array answers{Quantity::Kind::bucklingFactor,
                                      Quantity::Kind::sectionProperty};
  static constexpr bool needsMass = false;
  void read(const reader::Context& c, const Field& f);
  int modes = 4;
  bool reversed = false;  ///< also the negative load factors (the load reversed)
};

/// `type: moving-load`: a train of point loads (wheels) crossing a path of members (a frame)
/// or the whole line; the influence line of each quantity named under `quantities:` and its
/// envelope under the train, with the train's position that governs (ReadMovingLoad.cpp).
struct MovingLoadSpec {
  static constexpr std::string_view deckType = "moving-load";
  static constexpr std::array answers{Quantity::Kind::movingMax, Quantity::Kind::movingMin,
                                      Quantity::Kind::sectionProperty};
  static constexpr bool needsMass = false;
  void read(const reader::Context& c, const Field& f);
  struct Wheel {
    double force = 0;   ///< N, along `direction`
    double offset = 0;  ///< m behind the first wheel
  };
  /// A frame's members in the order the train crosses them; empty for a line (the whole line).
  std::vector<std::string> path;
  std::array<double, 3> direction{0, -1, 0};  ///< of the wheels' forces, global (normalised)
  std::vector<Wheel> wheels;
  std::vector<Quantity> quantities;  ///< reactions, displacements, resultants at points
  double pathLength = 0;             ///< m
  /// The deck's own `loads:` stand on the structure while the train crosses: their static
  /// value is added to each envelope (`deck_loads: false` gives the train alone).
  bool deckLoads = true;
  /// Every node's and line element's envelope too (`field_envelopes: true`), for the VTK file:
  /// its cost grows with the path's elements times the model's size, so it is asked for.
  bool fieldEnvelopes = false;
  DeckPlace place;
};

/// Response-spectrum analysis (fem/modal/ResponseSpectrum.hpp): the modes' peak responses to
/// a spectrum of ground acceleration, combined over the modes and the directions.
struct ResponseSpectrumSpec {
  static constexpr std::string_view deckType = "response-spectrum";
  static constexpr std::array answers{Quantity::Kind::spectrum, Quantity::Kind::effectiveMass,
                                      Quantity::Kind::frequency, Quantity::Kind::sectionProperty};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
  ResponseSpectrumOptions options;
  DesignSpectrum spectrum;
  int modes = 12;  ///< the options' modes (modesComputed reads it)
};

/// Harmonic motion of the ground (fem/modal/BaseMotion.hpp) over a range of frequencies.
struct BaseMotionSpec {
  static constexpr std::string_view deckType = "base-motion";
  static constexpr std::array answers{Quantity::Kind::baseMotion, Quantity::Kind::sectionProperty};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
  BaseMotionOptions options;
  int modes = 12;  ///< modal method: modes taken (modesComputed reads it)
};

}  // namespace beamrotor
