// The rows of the table of analysis kinds (problems/deck/AnalysisKinds.hpp) that solve the
// beams and frames as they are: statics (second_order: true included), modes (prestressed:
// true included) and buckling. Each row states its deck type, its reader and the check
// quantities it answers.
#pragma once

#include "problems/deck/AnalysisRow.hpp"

namespace beamrotor {

struct StaticSpec {
  static constexpr std::string_view deckType = "static";
  static constexpr std::array answers{
      Quantity::Kind::reaction,    Quantity::Kind::displacement,    Quantity::Kind::maxStress,
      Quantity::Kind::maxShear,    Quantity::Kind::maxMoment,       Quantity::Kind::maxDisplacement,
      Quantity::Kind::memberForce, Quantity::Kind::memberDeflection};
  static constexpr bool needsMass = false;
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct ModalSpec {
  static constexpr std::string_view deckType = "modal";
  static constexpr std::array answers{Quantity::Kind::frequency};
  static constexpr bool needsMass = true;
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct BucklingSpec {
  static constexpr std::string_view deckType = "buckling";
  static constexpr std::array answers{Quantity::Kind::bucklingFactor};
  static constexpr bool needsMass = false;
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

}  // namespace beamrotor
