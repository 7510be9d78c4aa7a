// What the rotor analyses of a deck produce (alternatives of RunResult's AnalysisResult): plain
// results of fem/rotor/ plus the names the writers need to label them.
#pragma once

#include <array>
#include <concepts>
#include <optional>
#include <string>
#include <vector>

#include "elements/PlainJournalBearing.hpp"
#include "fem/rotor/Api684.hpp"
#include "fem/rotor/CriticalSpeedMap.hpp"
#include "fem/rotor/GravityLoads.hpp"
#include "fem/rotor/LevelOneStability.hpp"
#include "fem/rotor/RotorFrequencyResponse.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "fem/runup/RunUp.hpp"
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

/// A plain journal or tilting-pad bearing's operating points over its table speeds: what the
/// model uses.
struct JournalBearingCurve {
  std::string name;
  std::string type;  ///< the deck's type: plain-journal or tilting-pad
  PlainJournal journal;
  std::vector<double> speeds;                     ///< rad/s
  std::vector<double> eccentricity;               ///< eccentricity ratio e / c (bearing's c)
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

// One result type per rotor analysis kind, each holding only what its kind produces; the
// damped modes at one speed (`rotor`) are fem/rotor/'s RotorModesResult itself, and the rigid
// body (`rigid-body`) is RigidBodyOutcome above.

/// campbell: the diagram, where its lines meet the excitation orders, and its stability.
struct CampbellOutcome {
  CampbellResult campbell;
  double order = 1;                           ///< the order the critical speeds are read at
  std::vector<CriticalSpeed> criticalSpeeds;  ///< where lines meet order x speed
  std::vector<double> furtherOrders;          ///< the deck's further orders, as in the deck
  /// Crossings with the further orders (each tagged with its order), by order then speed; not
  /// part of the critical speeds the checks and API margins read
  std::vector<CriticalSpeed> furtherCriticalSpeeds;
  /// The lowest speed where a mode's log decrement falls through zero, refined on the speed;
  /// none when every mode stays stable over the sweep
  std::optional<InstabilityOnset> onset;
  std::vector<JournalBearingCurve> journals;  ///< the deck's loaded journal and tilting-pad bearings
  /// The operating range of the deck's first unbalance analysis giving one (drawn on the
  /// charts); none without such an analysis
  std::optional<OperatingRange> operating;
};

/// unbalance: the response at its points over the speeds, and with an operating range the
/// API 684 reading of it.
struct UnbalanceOutcome {
  UnbalanceResult unbalance;
  /// names of unbalance.nodes: the deck's response points, then the housing of each bearing on
  /// a pedestal as "<bearing>_pedestal" (its peaks empty: API 684 reads the shaft)
  std::vector<std::string> responsePoints;
  /// The operating range its API 684 reading measures margins from; none without one (and
  /// then no peaks and no stability either)
  std::optional<OperatingRange> operating;
  std::vector<std::vector<ResponsePeak>> peaks;  ///< peaks[k]: responsePoints[k]'s
  std::optional<OperatingStability> stability;   ///< the stability half of the verdict

  /// The API 684 verdict: every peak's separation margin and the stability half pass (false
  /// without an operating range, which has no verdict).
  bool api684Pass() const {
    if (!operating) return false;
    for (const auto& point : peaks)
      for (const ResponsePeak& p : point)
        if (!p.pass) return false;
    return !stability || stability->pass;
  }
};

/// frequency-response: the receptance between two dofs at one spin speed.
struct FrequencyResponseOutcome {
  FrequencyResponseResult response;
  std::string input, output;  ///< "point dof" of each end
};

/// critical-speed-map: the undamped critical speeds against bearing stiffness, with the
/// speed-dependent bearings drawn over them.
struct CriticalSpeedMapOutcome {
  CriticalSpeedMap map;
  std::vector<BearingStiffnessCurve> bearings;  ///< the deck's speed-dependent bearings
  double time = 0;                              ///< wall time (s)
};

/// bearing-loads: the rotor's weight on its bearings and its sag.
struct BearingLoadsOutcome {
  GravityLoads loads;
  std::vector<std::string> bearingNames;  ///< loads.bearings' names
  bool rigidBearings = true;              ///< bearings pinned (else elastic)
  double time = 0;                        ///< wall time (s)
};

/// level1-stability: API 684's Level I screening at one speed.
struct LevelOneOutcome {
  LevelOneResult screening;
  std::string station;  ///< the point the cross-coupling was added at
  int stages = 0;       ///< how many stages make up Qa
  double time = 0;      ///< wall time (s)
};

/// run-up: the rotor driven through its speeds in time.
struct RunUpOutcome {
  RunUpResult runUp;
  std::vector<std::string> responsePoints;  ///< names of runUp.histories' nodes, in order
  std::vector<std::string> rubPoints;       ///< the point of each of runUp.rubs, in order
  bool steadyStart = false;                 ///< started on the steady orbit (else at rest)
  double alpha = 0;                         ///< HHT's alpha (0: average acceleration)
  double inertia = 0;  ///< driven speed: the polar inertia driven (kg m^2); 0 when prescribed
};

/// The result of any rotor analysis: the writers take each through one overload set
/// (rotorJson, prepareRotor, printRotor, ...), so one visitor lambda covers the family, and a
/// kind missing from a set does not compile.
template <class R>
concept RotorResult = std::same_as<R, RotorModesResult> || std::same_as<R, CampbellOutcome> ||
    std::same_as<R, UnbalanceOutcome> || std::same_as<R, RigidBodyOutcome> ||
    std::same_as<R, FrequencyResponseOutcome> || std::same_as<R, CriticalSpeedMapOutcome> ||
    std::same_as<R, BearingLoadsOutcome> || std::same_as<R, LevelOneOutcome> ||
    std::same_as<R, RunUpOutcome>;

}  // namespace beamrotor
