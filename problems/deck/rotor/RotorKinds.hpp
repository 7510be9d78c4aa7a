// The rotor analyses' rows in the table of analysis kinds (problems/deck/AnalysisKinds.hpp).
// They share the model's bearings and damping (DeckRotor.hpp), which RotorFamily marks.
#pragma once

#include "problems/deck/AnalysisRow.hpp"

namespace beamrotor {

/// The base of every rotor row: the runner hands these to the rotor solver, and all but the
/// rigid body read with the one rotor reader (ReadRotor.cpp).
struct RotorFamily {
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct RotorSpec : RotorFamily {
  static constexpr std::string_view deckType = "rotor";
  static constexpr std::array answers{Quantity::Kind::frequency, Quantity::Kind::logDecrement};
  static constexpr bool needsMass = true;
};

struct CampbellSpec : RotorFamily {
  static constexpr std::string_view deckType = "campbell";
  static constexpr std::array answers{Quantity::Kind::criticalSpeed};
  static constexpr bool needsMass = true;
};

struct UnbalanceSpec : RotorFamily {
  static constexpr std::string_view deckType = "unbalance";
  static constexpr std::array answers{Quantity::Kind::unbalanceAmplitude};
  static constexpr bool needsMass = false;
};

/// Also a mechanism without a model when given its `body:` (FORMAT.md).
struct RigidBodySpec : RotorFamily {
  static constexpr std::string_view deckType = "rigid-body";
  static constexpr std::array answers{Quantity::Kind::rigidBody};
  static constexpr bool needsMass = false;  // with `bearings:` its reader asks for it
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
  static bool modelFree(const Field& entry);
};

struct FrequencyResponseSpec : RotorFamily {
  static constexpr std::string_view deckType = "frequency-response";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static constexpr bool needsMass = true;
};

struct CriticalSpeedMapSpec : RotorFamily {
  static constexpr std::string_view deckType = "critical-speed-map";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static constexpr bool needsMass = true;
};

struct BearingLoadsSpec : RotorFamily {
  static constexpr std::string_view deckType = "bearing-loads";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static constexpr bool needsMass = true;
};

}  // namespace beamrotor
