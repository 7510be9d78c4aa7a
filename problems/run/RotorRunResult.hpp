// What the rotor analyses of a deck produce (part of RunResult's AnalysisOutcome): plain
// results of fem/rotor/ plus the names the writers need to label them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "elements/PlainJournalBearing.hpp"
#include "fem/rotor/Api684.hpp"
#include "fem/rotor/CriticalSpeedMap.hpp"
#include "fem/rotor/GravityLoads.hpp"
#include "fem/rotor/RotorFrequencyResponse.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "problems/scenes/FormeShaft.hpp"

namespace beamrotor {

/// A rigid body on two springs (problems/scenes/README.md section 2): the FE model's rigid-body
/// properties, the two spring stations and stiffnesses, and the two-dof closed form built from
/// them.
struct RigidBodyOutcome {
  RigidBodyProperties body;
  std::array<std::string, 2> points;  ///< names of the spring points A, B
  std::array<double, 2> x{};          ///< their stations (m)
  std::array<double, 2> stiffness{};  ///< C1, C2 (N/m)
  FormeShaftRigid rigid;
  std::array<FormeShaftMode, 2> modes;
};

/// A plain journal bearing's operating points over its table speeds: what the model uses.
struct JournalBearingCurve {
  std::string name;
  PlainJournal journal;
  std::vector<double> speeds;                     ///< rad/s
  std::vector<double> eccentricity;               ///< eccentricity ratio e / c
  std::vector<double> attitude;                   ///< attitude angle (rad)
  std::vector<double> sommerfeld;                 ///< mu Omega D L^3 / (8 W c^2)
  std::vector<BearingCoefficients> coefficients;  ///< global axes
};

/// A bearing's direct stiffnesses against speed (tabulated or plain journal), drawn over the
/// critical-speed map: where they cross a critical-speed line the rotor has that critical speed.
struct BearingStiffnessCurve {
  std::string name;
  std::vector<double> speeds;  ///< rad/s
  std::vector<double> kxx;     ///< N/m, the deck's kxx (global y)
  std::vector<double> kyy;     ///< N/m, the deck's kyy (global z)
  /// Where kxx and kyy meet the map's lines: the critical speeds on this bearing
  std::vector<MapCrossing> kxxCrossings, kyyCrossings;
};

/// One rotor analysis, solved: exactly one of the optionals is set, by its type.
struct RotorOutcome {
  std::optional<RotorModesResult> modes;      ///< rotor: damped modes at one speed
  std::optional<CampbellResult> campbell;     ///< campbell
  std::vector<CriticalSpeed> criticalSpeeds;  ///< campbell: where lines meet order x speed
  double order = 1;                           ///< campbell: that order
  /// campbell: crossings with the deck's further orders (each tagged with its order), by order
  /// then speed; not part of the critical speeds the checks and API margins read
  std::vector<CriticalSpeed> furtherCriticalSpeeds;
  std::vector<double> furtherOrders;  ///< campbell: those orders, as in the deck
  /// campbell: the lowest speed where a mode's log decrement falls through zero, refined on the
  /// speed; none when every mode stays stable over the sweep
  std::optional<InstabilityOnset> onset;
  std::vector<JournalBearingCurve> journals;  ///< campbell: the deck's plain journal bearings
  std::optional<UnbalanceResult> unbalance;   ///< unbalance
  std::vector<std::string> responsePoints;    ///< unbalance: names of unbalance->nodes
  /// unbalance: the operating range its API 684 reading measures margins from; campbell: that
  /// of the deck's first unbalance analysis giving one (drawn on its charts)
  std::optional<OperatingRange> operating;
  /// unbalance with an operating range: API 684 reading of each response point's peaks
  std::vector<std::vector<ResponsePeak>> peaks;  ///< peaks[k]: responsePoints[k]'s
  /// unbalance with an operating range: the stability half of the API 684 verdict
  std::optional<OperatingStability> stability;
  std::optional<RigidBodyOutcome> rigidBody;  ///< rigid-body
  std::optional<FrequencyResponseResult> frequencyResponse;  ///< frequency-response
  std::string frfInput, frfOutput;  ///< frequency-response: "point dof" of each end
  std::optional<CriticalSpeedMap> map;  ///< critical-speed-map
  std::vector<BearingStiffnessCurve> mapBearings;  ///< critical-speed-map: speed-dependent bearings
  double mapTime = 0;  ///< critical-speed-map: wall time (s)
  std::optional<GravityLoads> gravityLoads;  ///< bearing-loads
  std::vector<std::string> bearingNames;  ///< bearing-loads: gravityLoads->bearings' names
  bool rigidBearings = true;              ///< bearing-loads: bearings pinned (else elastic)
  double loadsTime = 0;                   ///< bearing-loads: wall time (s)
};

}  // namespace beamrotor
