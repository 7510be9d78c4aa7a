// The rotor-dynamics parts of a deck (see FORMAT.md, "Rotors"): bearings and proportional
// damping on the model, and what the rotor analyses (rotor, campbell, unbalance, rigid-body)
// ask for (also critical-speed-map). Plain values, read by ReadRotor.cpp and solved by RunRotor.cpp.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/FiniteJournalBearing.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/TiltingPadBearing.hpp"
#include "fem/rotor/Api684.hpp"
#include "fem/rotor/LevelOneStability.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

/// A pedestal (foundation) under a bearing: its mass, and its stiffness and damping to the
/// ground along global y (kxx, cxx) and z (kyy, cyy), in series with the bearing
/// (elements/BearingOnPedestal.hpp).
struct DeckPedestal {
  double m = 0;             ///< kg
  double kyy = 0, kzz = 0;  ///< N/m
  double cyy = 0, czz = 0;  ///< N s/m
};

/// A bearing at a point (elements/Bearing): constant coefficients (speeds empty, one row)
/// or a table against spin speed (speeds ascending, one row each). Global axes y, z.
struct DeckBearing {
  std::string name;
  std::string point;
  std::vector<double> speeds;              ///< rad/s; empty for constant coefficients
  std::vector<BearingCoefficients> table;  ///< N/m, N s/m (by whirl too: the synchronous set)
  /// A table by speed and whirl frequency (rows with `whirl_hz`): the whirl frequencies
  /// (rad/s, ascending, the same at every speed) and the rows, speed by speed
  /// (elements/WhirlTable.hpp); empty for a table by speed only.
  std::vector<double> whirls;
  std::vector<BearingCoefficients> whirlRows;
  /// A plain journal bearing (type: plain-journal): its geometry and oil; the table then holds
  /// its coefficients at `speeds`, by the short-bearing theory or the finite film (`model`).
  std::optional<PlainJournal> journal;
  enum class JournalModel { shortBearing, finite };
  JournalModel journalModel = JournalModel::shortBearing;
  ReynoldsGrid journalGrid;  ///< the finite film's grid (model: finite; one pad's, tilting pads)
  /// A tilting-pad bearing (type: tilting-pad): its pads; `journal` then holds its journal, oil,
  /// load and bearing clearance, and `table` the synchronously condensed coefficients.
  std::optional<TiltingPads> tiltingPads;
  /// The journal's operating point at each of `speeds` (what `table` was filled from).
  std::vector<JournalOperatingPoint> journalPoints;
  /// Tilting pads: the pads' states at each of `speeds`, from which the modes take the
  /// coefficients at their own eigenvalue (elements/TiltingPadWhirl.hpp) with
  /// `whirl_coefficients: each-mode` (eachModesWhirl); by default the synchronous set.
  std::vector<TiltingPadPoint> padPoints;
  bool eachModesWhirl = false;
  /// Tilting pads with `pad_tilts: dofs` (or {inertia: ...}): each pad loaded at some table
  /// speed keeps its tilt as a dof of the rotor's (elements/TiltingPadFilm.hpp), the pad's
  /// polar moment of inertia about its pivot padInertia (kg m^2); unset: condensed.
  std::optional<double> padInertia;
  /// With padInertia: every pad keeps its tilt, those loaded at no table speed too (a
  /// nonlinear run-up's model, whose pad films act on every tilt).
  bool everyPadTilt = false;
  /// A plain journal with `load: gravity`: its load is the rotor's weight share on pinned
  /// bearings, found when the deck runs (journal->load and table are empty until then).
  bool loadFromGravity = false;
  /// `load_angle`: the bearing's own axes (and a journal's load, along -x_b) turned by this
  /// angle (rad) about +x from global (y, z) (elements/TurnedBearing.hpp); the table stays in
  /// the bearing's axes, the model gets it turned.
  double loadAngle = 0;
  /// `pedestal:` the bearing's housing on a pedestal instead of the ground
  std::optional<DeckPedestal> pedestal;
  DeckPlace place;
};

/// An unbalance m e at a point, heavy spot at `phase` (rad from +y towards +z) at t = 0, and a
/// couple unbalance (fem/rotor/RotorUnbalance.hpp) at the same phase.
struct DeckUnbalance {
  std::string point;
  double me = 0;      ///< kg m
  double moment = 0;  ///< kg m^2
  double phase = 0;  ///< rad
  DeckPlace place;
};

/// The rotor parts of the model.
struct DeckRotorModel {
  std::vector<DeckBearing> bearings;
  ProportionalDamping damping;  ///< alpha M + beta K, used by the rotor analyses
};

/// What a rotor analysis asks for (the fields its type uses; the others stay empty).
/// rigid-body `body:`: the spring-mounted rigid body from its own inputs, with no beams
/// (problems/scenes/README.md section 2: weight Q, radius of gyration rho, l1, l2, C1, C2).
struct DeckTwoDofBody {
  double mass = 0;              ///< kg (`mass:`, or `weight:` over standard gravity)
  double radiusOfGyration = 0;  ///< about the centre of mass, in the plane of vibration (m)
  double l1 = 0, l2 = 0;        ///< centre of mass to spring A (-x side), to spring B (m)
  double C1 = 0, C2 = 0;        ///< spring stiffnesses at A and B (N/m)
};

/// run-up `speed:` the speed driven by a torque (fem/runup/SpeedDrive.hpp) against the rotor's
/// polar inertia plus `inertia`: a constant torque, a table against time or a motor curve.
struct DeckDrive {
  enum class Kind { constant, time, speed };
  Kind kind = Kind::constant;
  std::vector<double> x;        ///< time (s) or speed (rad/s) of each point; {0} for constant
  std::vector<double> torques;  ///< N m
  double extraInertia = 0;      ///< kg m^2, added to the model's spinning parts
};

/// run-up `rub:` a station that may touch a stator across a radial clearance, with Coulomb
/// friction (fem/runup/RubContact.hpp).
struct DeckRub {
  std::string name;          ///< `name:`, else the point's
  std::string point;         ///< `at:`
  double clearance = 0;      ///< m
  double stiffness = 0;      ///< N/m, the contact's penalty
  double damping = 0;        ///< N s/m, normal, in contact
  double friction = 0;       ///< Coulomb's mu
  double radius = 0;         ///< m, the shaft's radius at the contact
  double slipVelocity = 1e-3;  ///< m/s, the friction's regularisation
  DeckPlace place;
};

/// run-up: the spin speed against time and the time grid (fem/runup/RunUp.hpp).
struct DeckRunUp {
  std::vector<double> times;   ///< s, from 0, strictly ascending (a ramp: 0 and its duration)
  std::vector<double> speeds;  ///< rad/s at those times
  double dt = 0;               ///< s
  double alpha = 0;            ///< HHT's alpha, in [-1/3, 0]; 0: the average acceleration rule
  bool steadyStart = false;    ///< start on the steady unbalance orbit (else at rest)
  std::array<double, 3> gravity{0, 0, 0};  ///< m/s^2, global; zero without `gravity:`
  int sampleEvery = 1;                     ///< histories kept every n steps
  /// `bearings: nonlinear`: the plain journal bearings act by their film force at the
  /// journal's instantaneous position and velocity (fem/runup/JournalFilm.hpp)
  bool nonlinearBearings = false;
  /// `speed:` driven by a torque; times then holds {0, duration} and speeds the start speed
  std::optional<DeckDrive> drive;
  std::vector<DeckRub> rubs;  ///< `rub:` stations that may touch their stators
};

struct DeckRotorAnalysis {
  double speed = 0;                        ///< rotor: spin speed (rad/s)
  std::vector<double> speeds;              ///< campbell, unbalance: ascending (rad/s)
  double order = 1;                        ///< campbell: excitation order of the critical speeds
  std::vector<double> furtherOrders;       ///< campbell: more orders drawn, with their crossings
  std::vector<DeckUnbalance> unbalance;    ///< unbalance
  std::vector<std::string> response;       ///< unbalance: points whose orbits are reported
  /// unbalance: the operating speed range (rad/s) the API 684 margins are measured from
  std::optional<OperatingRange> operating;
  /// unbalance: `operating.min_log_decrement`, the smallest log decrement API 684's verdict
  /// allows a mode over the operating range (0: only an unstable mode fails)
  double minLogDecrement = 0;
  /// frequency-response: force on input.dof at input.point, response of output's (uy uz ry rz)
  std::string inputPoint, outputPoint;
  Dof inputDof = Dof::uy, outputDof = Dof::uy;
  std::vector<double> frequencies;  ///< frequency-response: excitation (rad/s), ascending
  std::vector<std::string> bearingPoints;  ///< rigid-body: the two spring points A, B
  std::optional<DeckTwoDofBody> body;      ///< rigid-body: the body given directly, no model
  /// critical-speed-map: bearing stiffnesses (N/m), ascending, equal steps of log k
  std::vector<double> stiffnesses;
  int criticalSpeeds = 4;  ///< critical-speed-map: critical speeds per stiffness
  /// bearing-loads: the acceleration of gravity (m/s^2, global; default 9.81 along -y)
  std::array<double, 3> gravity{0, -9.81, 0};
  bool rigidBearings = true;  ///< bearing-loads: bearings pinned, or their stiffness at `speed`
  /// level1-stability: the compressor's stages (API 617's Qa), at `speed`
  std::vector<CompressorStage> stages;
  /// level1-stability: the point the cross-coupling is added at; empty: mid-span
  std::string station;
  /// level1-stability: the maximum continuous speed (rad/s) of API's critical speed ratio;
  /// 0: `speed`
  double maximumContinuousSpeed = 0;
  /// level1-stability: API's average gas density (kg/m^3); unset: from the stages
  std::optional<double> averageGasDensity;
  DeckRunUp runUp;  ///< run-up

};

}  // namespace beamrotor
