// A deck's transient analysis after reading (see FORMAT.md, "Transient analysis"): the scheme,
// the time grid, damping, initial state, loads as functions of time and what to record.
#pragma once

#include <string>
#include <vector>

#include "fem/model/Dof.hpp"
#include "fem/transient/TimeLoad.hpp"
#include "fem/transient/Transient.hpp"
#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

/// A load on one dof of a point: value(t) in N or N m (the factor of a unit pattern).
struct DeckTimeLoad {
  std::string point;
  Dof dof = Dof::uy;
  TimeFunction value;
  DeckPlace place;
};

/// Initial displacement u (m, rad) and velocity v (m/s, rad/s) of one dof of a point.
struct DeckInitialState {
  std::string point;
  Dof dof = Dof::uy;
  double u = 0, v = 0;
  DeckPlace place;
};

/// A named history: a recorded dof (point and dof), or an expression of the earlier
/// histories' names, the parameters and t.
struct DeckHistory {
  std::string name;
  std::string point;  ///< recorded dof; empty for an expression
  Dof dof = Dof::uy;
  std::string expression;  ///< derived; empty for a recorded dof
  std::string unit;        ///< m or rad for a dof; as the deck says for an expression
  DeckPlace place;
};

struct DeckTransient {
  TimeScheme scheme = TimeScheme::newmark;
  double dt = 0;   ///< s
  double end = 0;  ///< s
  double hhtAlpha = -0.1;
  double rayleighMass = 0, rayleighStiffness = 0;  ///< C += alpha M + beta K (1/s, s)
  double restitution = 0;                          ///< of the contacts as stops in time
  int frames = 0;                                  ///< VTK frames, evenly spaced
  int sampleEvery = 1;                             ///< record every n steps
  std::vector<DeckInitialState> initial;
  std::vector<DeckTimeLoad> loads;
  std::vector<DeckHistory> histories;
  /// Start from the periodic steady state of the loads' period `period` (s) instead of rest
  /// (`periodic: true`, see fem/transient/PeriodicSteadyState); 0: not periodic.
  double periodicPeriod = 0;
  DeckPlace dtPlace;  ///< where dt is given, for the explicit stability error
  DeckPlace periodicPlace;  ///< where `periodic: true` is given, for the resonance error
};

}  // namespace beamrotor
