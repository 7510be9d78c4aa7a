// The rotor analyses' rows in the table of analysis kinds (problems/deck/AnalysisKinds.hpp).
// They share the model's bearings and damping (DeckRotor.hpp) and the settings RotorFamily
// holds; each row reads its own entry (ReadRotor.cpp).
#pragma once

#include "problems/deck/AnalysisRow.hpp"
#include "problems/deck/rotor/DeckRotor.hpp"

namespace beamrotor {

/// The base of every rotor row: what the rotor solver is handed.
struct RotorFamily {
  int modes = 6;     ///< damped modes sought (rotor, campbell; the stability of unbalance)
  double shift = 0;  ///< the damping rate d of s = -d + i w they are sought nearest (1/s)
  DeckRotorAnalysis rotor;  ///< speeds, unbalance, response points, ...
};

struct RotorSpec : RotorFamily {
  static constexpr std::string_view deckType = "rotor";
  static constexpr std::array answers{Quantity::Kind::frequency, Quantity::Kind::logDecrement,
                                      Quantity::Kind::padMode};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

struct CampbellSpec : RotorFamily {
  static constexpr std::string_view deckType = "campbell";
  static constexpr std::array answers{Quantity::Kind::criticalSpeed,
                                      Quantity::Kind::instabilityOnset};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

struct UnbalanceSpec : RotorFamily {
  static constexpr std::string_view deckType = "unbalance";
  static constexpr std::array answers{Quantity::Kind::unbalanceAmplitude};
  static constexpr bool needsMass = false;
  void read(const reader::Context& c, const Field& f);
};

/// Also a mechanism without a model when given its `body:` (FORMAT.md).
struct RigidBodySpec : RotorFamily {
  static constexpr std::string_view deckType = "rigid-body";
  static constexpr std::array answers{Quantity::Kind::rigidBody};
  static constexpr bool needsMass = false;  // with `bearings:` its reader asks for it
  void read(const reader::Context& c, const Field& f);
  static bool modelFree(const Field& entry);
};

struct FrequencyResponseSpec : RotorFamily {
  static constexpr std::string_view deckType = "frequency-response";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

struct CriticalSpeedMapSpec : RotorFamily {
  static constexpr std::string_view deckType = "critical-speed-map";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

struct BearingLoadsSpec : RotorFamily {
  static constexpr std::string_view deckType = "bearing-loads";
  static constexpr std::array<Quantity::Kind, 0> answers{};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

/// API 684 Level I stability screening at one speed (fem/rotor/LevelOneStability.hpp).
struct LevelOneSpec : RotorFamily {
  static constexpr std::string_view deckType = "level1-stability";
  static constexpr std::array answers{Quantity::Kind::levelOne};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

/// Run-up or coast-down through the critical speeds, stepped in time (fem/runup/RunUp.hpp).
struct RunUpSpec : RotorFamily {
  static constexpr std::string_view deckType = "run-up";
  static constexpr std::array answers{Quantity::Kind::runUp};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
};

}  // namespace beamrotor
