// The rotor analyses' rows in the table of analysis kinds (problems/deck/AnalysisKinds.hpp).
// They share the model's bearings and damping (DeckRotor.hpp), which RotorFamily marks.
#pragma once

#include <array>
#include <string_view>

#include "problems/deck/Quantity.hpp"

namespace beamrotor {

class Field;
struct DeckAnalysis;
namespace reader {
struct Context;
}

/// The base of every rotor row: the runner hands these to the rotor solver.
struct RotorFamily {};

struct RotorSpec : RotorFamily {
  static constexpr std::string_view deckType = "rotor";
  static constexpr std::array answers{Quantity::Kind::frequency, Quantity::Kind::logDecrement};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct CampbellSpec : RotorFamily {
  static constexpr std::string_view deckType = "campbell";
  static constexpr std::array answers{Quantity::Kind::criticalSpeed};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct UnbalanceSpec : RotorFamily {
  static constexpr std::string_view deckType = "unbalance";
  static constexpr std::array answers{Quantity::Kind::unbalanceAmplitude};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

/// Also a mechanism without a model when given its `body:` (FORMAT.md).
struct RigidBodySpec : RotorFamily {
  static constexpr std::string_view deckType = "rigid-body";
  static constexpr std::array answers{Quantity::Kind::rigidBody};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
  static bool modelFree(const Field& entry);
};

struct FrequencyResponseSpec : RotorFamily {
  static constexpr std::string_view deckType = "frequency-response";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct CriticalSpeedMapSpec : RotorFamily {
  static constexpr std::string_view deckType = "critical-speed-map";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

struct BearingLoadsSpec : RotorFamily {
  static constexpr std::string_view deckType = "bearing-loads";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

}  // namespace beamrotor
