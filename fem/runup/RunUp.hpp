// Run-up and coast-down: a rotor driven through its critical speeds at a prescribed speed
// Omega(t), stepped in time (Newmark's average acceleration rule or HHT, the rules of
// fem/transient/TransientNewmark.hpp) on
//   M q'' + (C(Omega) + Omega G) q' + (K(Omega) + Omega' G) q = f_unb(phi, Omega, Omega') + M g,
// the matrices of fem/rotor/RotorSystem.hpp at the instantaneous speed (bearings' coefficients,
// proportional and internal damping). The angular-acceleration term Omega' G: a body spinning
// at Omega about its tilted axis a + theta x a carries the lateral angular momentum
// Jp Omega theta x a, whose rate Jp Omega theta' x a + Jp Omega' theta x a is G theta' Omega +
// G theta Omega' with the G the gyroscopic matrix is built from (PointInertia.cpp, Beam.cpp).
// Lalanne and Ferraris (Rotordynamics Prediction in Engineering, 1998, ch. 2) reach a
// one-entry matrix instead, from Euler angles whose spin angle differs from the body-axis
// angle by a second-order term; the two differ by a symmetric part. Omega G q' does no work
// (G skew); Omega' G q does, Omega' q'^T G q: the drive's share as the lateral angular
// momentum grows with the spin (zero without polar inertia, as on a Jeffcott rotor).
// An unbalance m e at phase p (fem/rotor/RotorUnbalance.hpp) pushes with
//   m e (Omega^2 cos(phi + p) + Omega' sin(phi + p), Omega^2 sin(phi + p) - Omega' cos(phi + p)),
// minus its mass times the acceleration of the heavy spot on its circle of radius e; a couple
// U_c the moments of its two opposite heavy spots.
// The effective matrix changes with the speed: it is factorised each step on one symbolic
// analysis (a step at an unchanged speed keeps its factor).
// Journal bearings may act by their film force instead (fem/runup/JournalFilm.hpp): the force
// at the journal's instantaneous position and velocity and the instantaneous speed, in place of
// their linear coefficients (a film may own dofs, a tilting pad's tilt: their elements'
// coefficients are taken out too, and the film acts on them); each implicit step is then
// solved by Newton's method on the film's exact derivatives (docs/runup.md). Rub stations
// (fem/runup/RubContact.hpp) add their contact and friction forces the same way, and their
// friction's torque brakes a driven spin.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "fem/rotor/RotorUnbalance.hpp"
#include "fem/runup/JournalFilm.hpp"
#include "fem/runup/RevolutionAmplitude.hpp"
#include "fem/runup/RubContact.hpp"
#include "fem/runup/SpeedDrive.hpp"
#include "fem/runup/SpeedProfile.hpp"

namespace beamrotor {

/// How the run starts at t = 0.
enum class RunUpStart {
  /// At rest on the static deflection under gravity (K(Omega_0) q = M g), then the unbalance
  /// builds up from there.
  rest,
  /// On the steady synchronous unbalance orbit at the start speed plus the static deflection:
  /// what a coast-down from a running machine starts from (no start-up transient).
  steady,
};

struct RunUpOptions {
  double timeStep = 0;  ///< s, constant
  double hhtAlpha = 0;  ///< in [-1/3, 0]; 0: Newmark's average acceleration rule
  RunUpStart start = RunUpStart::rest;
  std::vector<Unbalance> unbalance;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< m/s^2, global
  ProportionalDamping damping;
  std::vector<int> nodes;  ///< nodes whose uy, uz are recorded (histories and amplitudes)
  int sampleEvery = 1;     ///< histories kept every n steps (and the last); amplitudes use all
  /// Bearings acting by their nonlinear film force (their linear coefficients are taken out)
  std::vector<NonlinearJournal> journals;
  /// Stations that may rub on a stator across a clearance, with friction
  std::vector<RubContact> rubs;
  /// Newton's tolerance on the state: a step is converged when its last correction moved no
  /// dof by more than this fraction of the smallest journal or rub clearance
  double newtonTolerance = 1e-10;
};

/// A nonlinear journal's motion in its bearing at RunUpResult::times.
struct JournalTrack {
  std::string name;
  double clearance = 0;  ///< c (m)
  /// The journal centre from the bearing's centre (m, global y and z)
  std::vector<double> y, z;
  std::vector<double> eccentricity;  ///< |journal centre - bearing centre| / c
  double largestEccentricity = 0;    ///< over every step, not only the samples
  double startEccentricity = 0;      ///< the film's own equilibrium at the start speed
  /// A film with dofs of its own (a tilting-pad bearing's pads' tilts, rad): their names
  /// (BearingFilm::ownDofName) and values at the samples
  std::vector<std::string> ownNames;
  std::vector<std::vector<double>> own;

  /// Own dof k's smallest and largest value over the samples; none without samples.
  std::optional<std::pair<double, double>> ownRange(std::size_t k) const;
};

/// A rub station's contact over the run: sampled at RunUpResult::times, summed over every step.
struct RubTrack {
  std::string name;
  double clearance = 0;  ///< c (m)
  std::vector<double> radial;    ///< |station centre| (m)
  std::vector<double> normal;    ///< N (N)
  std::vector<double> friction;  ///< mu N s(v_s) (N, signed: > 0 opposes a forward slip)
  std::vector<double> torque;    ///< mu N s R on the spin (N m)
  double contactTime = 0;        ///< s, the steps that end in contact times dt
  double firstContact = -1;      ///< s, the end of the first step in contact; -1: never
  double peakNormal = 0, peakTorque = 0;  ///< over every step (N, N m; |torque|)
  /// Energy the contact dissipated (J, trapezoidal in time): by friction, by its normal damper
  double frictionWork = 0, dampingWork = 0;
};

/// One recorded node's motion (m, global y and z) at RunUpResult::times.
struct RunUpHistory {
  int node = -1;
  std::vector<double> uy, uz;
  RevolutionAmplitudes revolutions;  ///< from every step, not only the samples
  /// The largest per-revolution amplitude and the revolution's mean speed (rad/s) and end time.
  double peakAmplitude = 0, speedAtPeak = 0, timeAtPeak = 0;
};

/// The energy account at the sample times (J). With Newmark's average acceleration rule and
/// speed-independent K, kinetic + strain + dissipated + gyroscopic - work - (kinetic + strain
/// at t = 0) vanishes to round-off; with HHT the shortfall is the energy the scheme damps.
struct RunUpEnergy {
  std::vector<double> kinetic;     ///< 1/2 v' M v
  std::vector<double> strain;      ///< 1/2 u' K(Omega) u (the symmetric part)
  std::vector<double> dissipated;  ///< work done against C(Omega) so far
  /// Work of the unbalance forces and gravity so far (trapezoidal in the displacement
  /// increments, as the average acceleration rule's own balance)
  std::vector<double> work;
  /// Work done against the nonlinear films and the loads they carry so far (trapezoidal)
  std::vector<double> film;
  /// Work done against Omega G q' + Omega' G q so far: the first part is zero in the
  /// continuous system (G skew), the second is the drive's, -integral of Omega' q'^T G q
  std::vector<double> gyroscopic;
  /// Work done against the rub stations' contact and friction forces so far (trapezoidal)
  std::vector<double> rub;
  double balance(std::size_t i) const {
    return kinetic[i] + strain[i] + dissipated[i] + gyroscopic[i] + film[i] + rub[i] - work[i] -
           (kinetic[0] + strain[0]);
  }
};

struct RunUpResult {
  std::vector<double> times;  ///< sample times (s), t = 0 included
  std::vector<double> speed;  ///< Omega at the samples (rad/s)
  std::vector<double> angle;  ///< phi at the samples (rad)
  bool driven = false;        ///< the speed driven by a torque (SpeedDrive), not prescribed
  /// Driven: the drive's torque and the unbalances' torque on the spin at the samples (N m; the
  /// rubs' torques are in RubTrack)
  std::vector<double> driveTorque, unbalanceTorque;
  /// With nonlinear journals: the films' drag torque on the spin at the samples (N m; it brakes
  /// a driven speed, and a prescribed one's drive supplies it)
  std::vector<double> filmTorque;
  std::vector<RunUpHistory> histories;  ///< one per requested node, in request order
  RunUpEnergy energy;
  double timeStep = 0;  ///< s
  int steps = 0;
  int factorizations = 0;              ///< numeric factorisations of the effective matrix
  std::vector<JournalTrack> journals;  ///< one per nonlinear journal, in RunUpOptions' order
  std::vector<RubTrack> rubs;          ///< one per rub station, in RunUpOptions' order
  int newtonIterations = 0;            ///< over all steps (one per step without nonlinear journals)
  int mostNewtonIterations = 0;        ///< in any one step
  SystemSize size;
  SolveTimings time;
};

/// Runs the rotor through `profile`. Throws std::invalid_argument for bad options (a
/// non-positive step, alpha outside [-1/3, 0], an unbalance or recorded node without free uy
/// and uz) and SolveError for a singular effective matrix or a Newton iteration that does not
/// converge; JournalLeftClearance when a journal reaches its bearing's wall.
RunUpResult solveRunUp(const Model& model, const SpeedProfile& profile,
                       const RunUpOptions& options);

/// Runs the rotor with its speed driven by `drive` (fem/runup/SpeedDrive.hpp): J Omega' =
/// T(t, Omega) - T_unbalance, Omega by the trapezoid rule and phi by the average acceleration
/// rule, solved with each step's lateral motion. Throws as the prescribed run, and
/// std::invalid_argument for a non-positive inertia or duration.
RunUpResult solveRunUp(const Model& model, const SpeedDrive& drive, const RunUpOptions& options);

}  // namespace beamrotor
