// The run-up driver: the rotor's matrices at each step's speed, the HHT step on them, and the
// histories, per-revolution amplitudes and energy account kept while stepping.
#include "fem/runup/RunUp.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "fem/rotor/DynamicStiffness.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/RotorFactor.hpp"
#include "fem/solvers/StepFactor.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "fem/transient/TransientNewmark.hpp"

namespace beamrotor {

namespace {

/// Newton's iterations allowed in one step (quadratic convergence needs a handful).
constexpr int kMostNewtonIterations = 30;

/// The spin at one instant: speed (rad/s), angular acceleration (rad/s^2), angle (rad).
struct Spin {
  double speed = 0, acceleration = 0, angle = 0;
};

/// The equations of motion at one instant: the matrices at its speed and acceleration, and
/// the load at its angle.
struct Instant {
  double t = 0, speed = 0, acceleration = 0, angle = 0;
  SparseMatrix K;  ///< K(Omega) (the bearings' and internal damping's at that speed)
  SparseMatrix C;  ///< C(Omega)
  Eigen::VectorXd f;
};

/// A nonlinear journal placed in the equations: its dofs, where u = 0 puts it in its bearing
/// and the constant load it carries.
struct PlacedJournal {
  const NonlinearJournal* journal = nullptr;
  int y = -1, z = -1;           ///< equations of uy, uz
  std::vector<int> equations;   ///< of the film's state: uy, uz, then its own dofs
  /// The film's state at u = 0: the journal centre (m, from the bearing's centre), then its
  /// own dofs at rest
  Eigen::VectorXd offset;
  Eigen::Vector2d appliedLoad;  ///< N, on the journal (zero when gravity carries it)
  Eigen::VectorXd noForce;      ///< zeros on the film's state: the drag's Couette part alone
  /// The film's state at (u, v): offset + u, v on its equations.
  std::pair<Eigen::VectorXd, Eigen::VectorXd> state(const Eigen::VectorXd& u,
                                                    const Eigen::VectorXd& v) const {
    Eigen::VectorXd x = offset, r(offset.size());
    for (std::size_t i = 0; i < equations.size(); ++i) {
      x[Eigen::Index(i)] += u[equations[i]];
      r[Eigen::Index(i)] = v[equations[i]];
    }
    return {x, r};
  }
  Eigen::Vector2d journalCentre(const Eigen::VectorXd& u) const {
    return offset.head<2>() + Eigen::Vector2d(u[y], u[z]);
  }
};

/// The films' and rubs' forces (the films' constant loads included) on the whole system, their
/// derivatives, and the torques they put on the spin.
struct FilmForces {
  Eigen::VectorXd force;
  Eigen::VectorXd rubForce;     ///< the rubs' share of force
  std::vector<FilmLoad> each;   ///< per journal, for the tangent matrices
  std::vector<RubForce> rubs;   ///< per rub station
  /// The torque the rubs' friction and the films' drag take from the spin (N m) and its slope
  /// in the speed (N m s)
  double rubTorque = 0, dragTorque = 0, torqueSlope = 0;
};

/// A rub station placed in the equations: the equations of its uy, uz.
struct PlacedRub {
  const RubContact* rub = nullptr;
  int y = -1, z = -1;
};

/// The free equations of uy and uz at `node`; throws naming `what` (a recorded node, a rub
/// station, ...) when either is not free.
std::pair<int, int> lateralEquations(const RotorSystem& rotor, int node, const std::string& what) {
  const DofMap& dofs = rotor.dofs();
  if (node < 0 || node >= rotor.model().nodeCount())
    throw std::invalid_argument("run-up: " + what + " has no node " + std::to_string(node));
  const int y = dofs.equation(node, Dof::uy), z = dofs.equation(node, Dof::uz);
  if (!dofs.isFree(y) || !dofs.isFree(z))
    throw std::invalid_argument("run-up: " + what + " needs free uy and uz, not " +
                                rotor.model().describe({node, Dof::uy}));
  return {y, z};
}

class RunUpSystem {
 public:
  RunUpSystem(const Model& model, double startSpeed, const RunUpOptions& o)
      : rotor_(model, o.damping), unbalanceList_(o.unbalance), gravity_(o.gravity) {
    unbalance_ = unbalanceForces(rotor_, o.unbalance);
    placeJournals(model, startSpeed, o);
    placeRubs(o);
    // The weight as GravityLoads takes it: f = M a with a = g on every translation.
    const DofMap& dofs = rotor_.dofs();
    Eigen::VectorXd a = Eigen::VectorXd::Zero(rotor_.size());
    for (int eq = 0; eq < rotor_.size(); ++eq) {
      const Dof d = dofs.dofOf(eq).dof;
      if (d == Dof::ux || d == Dof::uy || d == Dof::uz) a[eq] = o.gravity[dofIndex(d)];
    }
    weight_ = rotor_.mass() * a;
  }

  const RotorSystem& rotor() const { return rotor_; }
  const Eigen::VectorXd& weight() const { return weight_; }
  const Eigen::VectorXcd& unbalance() const { return unbalance_; }

  Instant at(double t, const Spin& spin) const {
    Instant i;
    i.t = t;
    i.speed = spin.speed;
    i.acceleration = spin.acceleration;
    i.angle = spin.angle;
    i.K = rotor_.stiffness(i.speed);
    i.C = rotor_.damping(i.speed);
    // The nonlinear journals' linear coefficients out: their films act instead.
    for (const PlacedJournal& j : journals_) {
      const auto take = [&](int index, const std::vector<int>& equations) {
        const auto& element =
            static_cast<const SpeedDependentElement&>(*rotor_.model().elements()[index]);
        subtract(i.K, equations, element.stiffnessAt(i.speed));
        subtract(i.C, equations, element.dampingAt(i.speed));
      };
      if (j.journal->element >= 0) take(j.journal->element, {j.y, j.z});
      for (std::size_t k = 0; k < j.journal->ownElements.size(); ++k)
        take(j.journal->ownElements[k], {j.y, j.z, j.equations[2 + k]});
    }
    // Re(f e^{i phi} (Omega^2 - i Omega')): see unbalanceForces.
    const std::complex<double> turn =
        std::polar(1.0, i.angle) * std::complex<double>(i.speed * i.speed, -i.acceleration);
    i.f = weight_ + (unbalance_ * turn).real();
    return i;
  }

  const std::vector<PlacedJournal>& journals() const { return journals_; }
  const std::vector<PlacedRub>& rubs() const { return rubs_; }

  /// The films' and rubs' forces at the state (u, v) and speed, with the loads the films carry.
  FilmForces films(const Eigen::VectorXd& u, const Eigen::VectorXd& v, double speed) const {
    FilmForces out;
    out.rubForce = Eigen::VectorXd::Zero(rotor_.size());
    out.rubs.reserve(rubs_.size());
    out.each.reserve(journals_.size());
    for (const PlacedRub& r : rubs_) {
      RubForce f = rubForce(*r.rub, Eigen::Vector2d(u[r.y], u[r.z]),
                            Eigen::Vector2d(v[r.y], v[r.z]), speed);
      out.rubForce[r.y] += f.force[0];
      out.rubForce[r.z] += f.force[1];
      out.rubTorque += f.torque;
      out.torqueSlope += f.torqueSlope;
      out.rubs.push_back(std::move(f));
    }
    out.force = out.rubForce;
    for (const PlacedJournal& j : journals_) {
      const auto [x, rate] = j.state(u, v);
      FilmLoad f;
      try {
        f = j.journal->film->loadAt(x, rate, speed);
      } catch (const JournalLeftClearance& e) {
        throw JournalLeftClearance("bearing '" + j.journal->name + "': " + e.what());
      }
      for (std::size_t i = 0; i < j.equations.size(); ++i)
        out.force[j.equations[i]] += f.force[Eigen::Index(i)];
      out.force[j.y] += j.appliedLoad[0];
      out.force[j.z] += j.appliedLoad[1];
      // The drag's slope in the speed: its Couette part's (linear in Omega); the pressure
      // part's dependence is left to the drive's fixed point.
      out.dragTorque += j.journal->film->dragTorqueAt(x, f.force, speed);
      if (speed > 0)
        out.torqueSlope += j.journal->film->dragTorqueAt(x, j.noForce, speed) / speed;
      out.each.push_back(std::move(f));
    }
    return out;
  }

  /// A += the films' stiffness (or damping) times `scale`, on the pattern's existing entries.
  void addTangents(SparseMatrix& A, const FilmForces& f, double stiffness, double damping) const {
    const auto add = [&](const std::vector<int>& eq, const auto& K, const auto& C) {
      for (std::size_t r = 0; r < eq.size(); ++r)
        for (std::size_t c = 0; c < eq.size(); ++c)
          A.coeffRef(eq[r], eq[c]) += stiffness * K(Eigen::Index(r), Eigen::Index(c)) +
                                      damping * C(Eigen::Index(r), Eigen::Index(c));
    };
    for (std::size_t k = 0; k < journals_.size(); ++k)
      add(journals_[k].equations, f.each[k].stiffness, f.each[k].damping);
    for (std::size_t k = 0; k < rubs_.size(); ++k)
      add({rubs_[k].y, rubs_[k].z}, f.rubs[k].stiffness, f.rubs[k].damping);
  }

  /// The torque the unbalances take from the spin (N m): the heavy spot m e at angle
  /// psi = phi + p rides on the shaft's centre, whose acceleration a and gravity g pull it
  /// back, m e (-sin psi (a_y - g_y) + cos psi (a_z - g_z)) (the spin's equation of a disk
  /// with a heavy spot, Lagrange's equation in phi; its m e^2 phi'' is left out, e << radius
  /// of gyration).
  double unbalanceTorque(const Eigen::VectorXd& acceleration, double angle) const {
    const DofMap& dofs = rotor_.dofs();
    double torque = 0;
    for (const Unbalance& u : unbalanceList_) {
      const int y = dofs.equation(u.node, Dof::uy), z = dofs.equation(u.node, Dof::uz);
      const double ay = dofs.isFree(y) ? acceleration[y] : 0;
      const double az = dofs.isFree(z) ? acceleration[z] : 0;
      const double psi = angle + u.phase;
      torque += u.me * (-std::sin(psi) * (ay - gravity_[1]) + std::cos(psi) * (az - gravity_[2]));
    }
    return torque;
  }

  /// Omega G q' + Omega' G q: the gyroscopic and angular-acceleration forces.
  Eigen::VectorXd gyroscopicForce(const Instant& i, const TransientState& s) const {
    return rotor_.gyroscopic() * (i.speed * s.v + i.acceleration * s.u);
  }

 private:
  /// A -= m, m over `eq` (an element's matrix in its dofs' order).
  static void subtract(SparseMatrix& A, const std::vector<int>& eq, const ElementMatrix& m) {
    if (m.size() == 0) return;
    for (std::size_t r = 0; r < eq.size(); ++r)
      for (std::size_t c = 0; c < eq.size(); ++c)
        A.coeffRef(eq[r], eq[c]) -= m(Eigen::Index(r), Eigen::Index(c));
  }

  /// Whether element `index` of `model` is speed-dependent with exactly the dofs `dofs`.
  static bool holds(const Model& model, int index, const std::vector<NodeDof>& dofs) {
    const auto* element =
        index >= 0 && index < int(model.elements().size())
            ? dynamic_cast<const SpeedDependentElement*>(model.elements()[index].get())
            : nullptr;
    if (!element || element->dofs().size() != dofs.size()) return false;
    for (std::size_t i = 0; i < dofs.size(); ++i)
      if (element->dofs()[i] != dofs[i]) return false;
    return true;
  }

  void placeJournals(const Model& model, double startSpeed, const RunUpOptions& o) {
    for (const NonlinearJournal& n : o.journals) {
      const NodeDof y{n.node, Dof::uy}, z{n.node, Dof::uz};
      const int own = n.film ? n.film->ownDofs() : 0;
      bool placed = n.film && int(n.ownElements.size()) == own && int(n.ownDofs.size()) == own &&
                    (own > 0 ? n.element < 0 : holds(model, n.element, {y, z}));
      for (int k = 0; placed && k < own; ++k)
        placed = holds(model, n.ownElements[std::size_t(k)], {y, z, n.ownDofs[std::size_t(k)]});
      if (!placed)
        throw std::invalid_argument(
            "run-up: nonlinear journal '" + n.name +
            "' is no bearing between its journal's uy, uz and the ground (or has no film, or "
            "its own dofs' elements do not match the film's)");
      PlacedJournal j;
      j.journal = &n;
      std::tie(j.y, j.z) = lateralEquations(rotor_, n.node, "nonlinear journal '" + n.name + "'");
      j.equations = {j.y, j.z};
      for (const NodeDof& d : n.ownDofs) {
        const int eq = rotor_.dofs().equation(d.node, d.dof);
        if (!rotor_.dofs().isFree(eq))
          throw std::invalid_argument("run-up: nonlinear journal '" + n.name + "' needs its " +
                                      rotor_.model().describe(d) + " free");
        j.equations.push_back(eq);
      }
      if (!(startSpeed > 0) && n.load.norm() > 0)
        throw std::invalid_argument(
            "run-up: a loaded journal bearing has no film at rest: its nonlinear run starts at "
            "a speed above 0 (bearing '" +
            n.name + "')");
      j.offset = n.film->restState(n.load, startSpeed);
      j.noForce = Eigen::VectorXd::Zero(j.offset.size());
      const bool gravityCarries = o.gravity.squaredNorm() > 0;
      j.appliedLoad = gravityCarries ? Eigen::Vector2d::Zero() : Eigen::Vector2d(n.load);
      journals_.push_back(j);
    }
  }

  void placeRubs(const RunUpOptions& o) {
    for (const RubContact& r : o.rubs) {
      if (!(r.clearance > 0 && r.stiffness > 0 && r.damping >= 0 && r.friction >= 0 &&
            r.radius > 0 && r.slipVelocity > 0))
        throw std::invalid_argument("run-up: rub '" + r.name +
                                    "' needs c, k, R, v_e > 0 and d, mu >= 0");
      PlacedRub p;
      p.rub = &r;
      std::tie(p.y, p.z) = lateralEquations(rotor_, r.node, "rub '" + r.name + "'");
      rubs_.push_back(p);
    }
  }

  RotorSystem rotor_;
  std::vector<PlacedRub> rubs_;
  std::vector<Unbalance> unbalanceList_;
  Eigen::Vector3d gravity_;
  Eigen::VectorXcd unbalance_;
  Eigen::VectorXd weight_;
  std::vector<PlacedJournal> journals_;
};

/// Newton on the static equilibrium K u - F_films(u, 0) = M g: the journals' films (and any rub
/// the weight presses on a stator) carrying the weight (the linear rest of the rotor in K).
void settleOnFilms(const RunUpSystem& system, const Instant& start, Eigen::VectorXd& u,
                   double tolerance, StepFactor& factor) {
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(u.size());
  for (int iteration = 0; iteration < kMostNewtonIterations; ++iteration) {
    const FilmForces films = system.films(u, v, start.speed);
    SparseMatrix K = start.K + start.acceleration * system.rotor().gyroscopic();
    system.addTangents(K, films, 1, 0);
    if (!factor.factorize(K))
      throw SolveError(
          "run-up: the rotor on its journal films has no static equilibrium at the "
          "start speed (its tangent stiffness is singular)");
    const Eigen::VectorXd du = factor.solve(
        Eigen::VectorXd(system.weight() + films.force -
                        (start.K + start.acceleration * system.rotor().gyroscopic()) * u));
    u += du;
    if (du.lpNorm<Eigen::Infinity>() <= tolerance) return;
  }
  throw SolveError(
      "run-up: Newton's iterations on the static equilibrium on the journal films "
      "did not converge at the start speed");
}

/// The initial state (RunUpStart): the static deflection under gravity at the start speed,
/// plus on request the steady unbalance orbit there, its acceleration from the equation of
/// motion. With nonlinear journals the rest is their films' equilibrium, the steady orbit the
/// linear one about it (a small start-up transient remains).
TransientState initialState(const RunUpSystem& system, const Instant& start, RunUpStart how,
                            double tolerance, StepFactor& factor) {
  const int n = system.rotor().size();
  TransientState s;
  s.u = Eigen::VectorXd::Zero(n);
  s.v = Eigen::VectorXd::Zero(n);
  const FilmForces rest = system.films(s.u, s.v, start.speed);
  SparseMatrix K = start.K, C = start.C;  // with the films' slopes there
  system.addTangents(K, rest, 1, 0);
  system.addTangents(C, rest, 0, 1);
  if (system.weight().squaredNorm() > 0) {
    if (!factor.factorize(K))
      throw SolveError(
          "run-up: the rotor has no static equilibrium under gravity at the start speed (its "
          "stiffness is singular: a rigid-body motion the bearings do not hold)");
    s.u = factor.solve(Eigen::VectorXd(system.weight() + rest.force));
    if (!system.journals().empty() || !system.rubs().empty())
      settleOnFilms(system, start, s.u, tolerance, factor);
  }
  if (how == RunUpStart::steady && start.speed > 0 && system.unbalance().squaredNorm() > 0) {
    using Complex = std::complex<double>;
    const double w = start.speed;
    const RotorSystem& r = system.rotor();
    RepeatedFactor<Complex> dynamic;
    const ComplexSparseMatrix Z = K.cast<Complex>() - (w * w) * r.mass().cast<Complex>() +
                                  Complex(0, w) * (C + w * r.gyroscopic()).cast<Complex>();
    factorizeDynamicStiffness(dynamic, Z, w, "run-up's steady start", "the start speed");
    const Eigen::VectorXcd q = dynamic.solve(Eigen::VectorXcd((w * w) * system.unbalance()));
    const Eigen::VectorXcd turn = q * std::polar(1.0, start.angle);
    s.u += turn.real();
    s.v += (turn * Complex(0, w)).real();
  }
  // M a = f - C v - K u - Omega G v - Omega' G u (+ the films; massless dofs at a = 0: the
  // first step's solve puts them in equilibrium).
  s.a = accelerationOf(system.rotor().mass(),
                       start.f + system.films(s.u, s.v, start.speed).force - start.C * s.v -
                           start.K * s.u - system.gyroscopicForce(start, s),
                       "run-up");
  return s;
}

/// Keeps the energy account step by step (RunUpEnergy), trapezoidal in the increments.
class EnergyAccount {
 public:
  EnergyAccount(const RunUpSystem& system, const Instant& i, const TransientState& s)
      : system_(system) {
    measure(i, s);
  }

  void advance(const Instant& i, const TransientState& s) {
    const Eigen::VectorXd du = s.u - u_;
    const Eigen::VectorXd f0 = f_, c0 = Cv_, g0 = gyro_, n0 = film_, r0 = rub_;
    measure(i, s);
    work_ += du.dot(f0 + f_) / 2;
    dissipated_ += du.dot(c0 + Cv_) / 2;
    gyroscopic_ += du.dot(g0 + gyro_) / 2;
    filmWork_ -= du.dot(n0 + film_) / 2;
    rubWork_ -= du.dot(r0 + rub_) / 2;
  }

  void record(RunUpEnergy& e) const {
    e.kinetic.push_back(kinetic_);
    e.strain.push_back(strain_);
    e.dissipated.push_back(dissipated_);
    e.work.push_back(work_);
    e.gyroscopic.push_back(gyroscopic_);
    e.film.push_back(filmWork_);
    e.rub.push_back(rubWork_);
  }

 private:
  void measure(const Instant& i, const TransientState& s) {
    u_ = s.u;
    f_ = i.f;
    Cv_ = i.C * s.v;
    gyro_ = system_.gyroscopicForce(i, s);
    const FilmForces nonlinear = system_.films(s.u, s.v, i.speed);
    rub_ = nonlinear.rubForce;
    film_ = nonlinear.force - rub_;
    kinetic_ = 0.5 * s.v.dot(system_.rotor().mass() * s.v);
    strain_ = 0.5 * s.u.dot(i.K * s.u);
  }

  const RunUpSystem& system_;
  Eigen::VectorXd u_, f_, Cv_, gyro_, film_, rub_;
  double kinetic_ = 0, strain_ = 0, work_ = 0, dissipated_ = 0, gyroscopic_ = 0, filmWork_ = 0,
         rubWork_ = 0;
};

/// Where the spin comes from: a prescribed profile, or a drive whose speed is a state.
struct SpinSource {
  const SpeedProfile* profile = nullptr;
  const SpeedDrive* drive = nullptr;
  double duration() const { return profile ? profile->duration() : drive->duration; }
  double startSpeed() const { return profile ? profile->startSpeed() : drive->startSpeed; }
  Spin prescribed(double t) const {
    return {profile->speed(t), profile->acceleration(t), profile->angle(t)};
  }
};

/// One implicit step's outcome: the state at t_n+1, the films there, Newton's iterations, and
/// the step's C + Omega G and K + Omega' G (for the residual at t_n+1).
struct StepOutcome {
  TransientState state;
  FilmForces films;
  int iterations = 0;
  SparseMatrix damping, stiffness;
};

RunUpResult runUp(const Model& model, const SpinSource& source, const RunUpOptions& o) {
  Stopwatch clock, total;
  const NewmarkRule rule(o.timeStep, o.hhtAlpha);
  if (o.sampleEvery < 1) throw std::invalid_argument("run-up: sampleEvery must be at least 1");
  const RunUpSystem system(model, source.startSpeed(), o);
  const RotorSystem& rotor = system.rotor();
  std::vector<std::pair<int, int>> recorded;
  for (int node : o.nodes) recorded.push_back(lateralEquations(rotor, node, "a recorded node"));

  RunUpResult out;
  out.timeStep = o.timeStep;
  out.steps = std::max(1, int(std::lround(source.duration() / o.timeStep)));
  out.histories.resize(o.nodes.size());
  std::vector<RevolutionAmplitude> trackers(o.nodes.size());
  for (std::size_t k = 0; k < o.nodes.size(); ++k) out.histories[k].node = o.nodes[k];
  out.driven = source.drive != nullptr;

  double smallestClearance = std::numeric_limits<double>::infinity();
  for (const NonlinearJournal& j : o.journals)
    smallestClearance = std::min(smallestClearance, j.film->clearance());
  for (const RubContact& r : o.rubs) smallestClearance = std::min(smallestClearance, r.clearance);
  const double tolerance = o.newtonTolerance * smallestClearance;  // m

  // The drive's torque balance J Omega' = T(t, Omega) - T_load(Omega) for Omega' when Omega
  // follows it by the trapezoid rule from (Omega_n, Omega'_n) over dt (Newton on a piecewise
  // linear T: exact in two iterations on one piece). The load (the unbalances', rubs' and films'
  // torques) comes from the last lateral step, linear in the speed about it: T_load + slope
  // (Omega - at).
  const SpeedDrive* drive = source.drive;
  if (drive && !(drive->inertia > 0))
    throw std::invalid_argument("run-up: a driven speed needs a positive polar inertia");
  struct LoadTorque {
    double torque = 0, slope = 0, at = 0;
  };
  const auto balance = [&](double t, double speed, double acceleration, double dt,
                           const LoadTorque& load) {
    double x = acceleration;
    for (int k = 0; k < 50; ++k) {
      const double w = speed + dt / 2 * (acceleration + x);
      const double g = drive->inertia * x - drive->torque.at(t, w) + load.torque +
                       load.slope * (w - load.at);
      const double dx = g / (drive->inertia + (load.slope - drive->torque.slope(t, w)) * dt / 2);
      x -= dx;
      if (std::abs(dx) <= 1e-15 * (std::abs(x) + std::abs(drive->torque.at(t, w)) / drive->inertia))
        break;
    }
    return x;
  };
  // The drive's torque tolerance on Omega' between the lateral step and the balance.
  const auto settled = [&](double a, double b, double t, double speed) {
    return std::abs(a - b) <=
           1e-12 * (std::abs(a) + std::abs(drive->torque.at(t, speed)) / drive->inertia + 1e-300);
  };

  StepFactor factor;
  Spin spin;
  Instant now;
  TransientState s;
  double unbalanceTorque = 0;
  LoadTorque load;  // the drive's load: unbalance, rubs and films
  const auto loadOf = [&](const FilmForces& f, double speed) {
    return LoadTorque{unbalanceTorque + f.rubTorque + f.dragTorque, f.torqueSlope, speed};
  };
  if (drive) {
    // Omega'_0 and the state's acceleration depend on each other through the unbalance's
    // tangential force and torque: a fixed point (a contraction: the coupling is (m e)^2 / (m J));
    // the rubs' and films' torques at the start state come in on the second pass.
    spin = {drive->startSpeed, drive->torque.at(0, drive->startSpeed) / drive->inertia, 0};
    for (int k = 0;; ++k) {
      now = system.at(0, spin);
      s = initialState(system, now, o.start, tolerance, factor);
      unbalanceTorque = system.unbalanceTorque(s.a, 0);
      load = loadOf(system.films(s.u, s.v, spin.speed), spin.speed);
      const double a = (drive->torque.at(0, spin.speed) - load.torque) / drive->inertia;
      if (settled(a, spin.acceleration, 0, spin.speed)) break;
      if (k == 50) throw SolveError("run-up: the drive's start acceleration did not settle");
      spin.acceleration = a;
    }
  } else {
    spin = source.prescribed(0);
    now = system.at(0, spin);
    s = initialState(system, now, o.start, tolerance, factor);
  }
  EnergyAccount energy(system, now, s);
  FilmForces films = system.films(s.u, s.v, now.speed);
  out.time.assembly = clock.lap();

  const auto sample = [&](bool keep) {
    for (std::size_t k = 0; k < recorded.size(); ++k) {
      const double y = s.u[recorded[k].first], z = s.u[recorded[k].second];
      trackers[k].add(now.t, now.angle, now.speed, y, z);
      if (!keep) continue;
      out.histories[k].uy.push_back(y);
      out.histories[k].uz.push_back(z);
    }
    if (!keep) return;
    out.times.push_back(now.t);
    out.speed.push_back(now.speed);
    out.angle.push_back(now.angle);
    if (drive) {
      out.driveTorque.push_back(drive->torque.at(now.t, now.speed));
      out.unbalanceTorque.push_back(unbalanceTorque);
    }
    if (!system.journals().empty()) out.filmTorque.push_back(films.dragTorque);
    energy.record(out.energy);
  };
  sample(true);

  // HHT with matrices that change in time (alpha = 0: the average acceleration rule):
  //   M a_n+1 + (1 + alpha) r_n+1 - alpha r_n = (1 + alpha) f_n+1 - alpha f_n,
  // r = (C + Omega G) v + (K + Omega' G) u - F_films(u, v), solved for a_n+1 with
  //   S = M + (1 + alpha) [gamma dt (C + Omega G + C_films) + beta dt^2 (K + Omega' G + K_films)]
  // at t_n+1: one solve without films, Newton's iterations with them (u and v follow a_n+1
  // through the rule; the films' slopes at the last iterate).
  const double a1 = 1 + rule.alpha, dt = rule.dt;
  const bool nonlinear = !system.journals().empty() || !system.rubs().empty();
  for (const PlacedJournal& j : system.journals()) {
    JournalTrack t;
    t.name = j.journal->name;
    t.clearance = j.journal->film->clearance();
    t.startEccentricity = j.offset.head<2>().norm() / t.clearance;
    for (int k = 0; k + 2 < int(j.equations.size()); ++k)
      t.ownNames.push_back(j.journal->film->ownDofName(k));
    t.own.resize(t.ownNames.size());
    out.journals.push_back(std::move(t));
  }
  const auto trackJournals = [&](bool keep) {
    for (std::size_t k = 0; k < out.journals.size(); ++k) {
      const PlacedJournal& j = system.journals()[k];
      JournalTrack& t = out.journals[k];
      const Eigen::Vector2d x = j.journalCentre(s.u);
      const double e = x.norm() / t.clearance;
      t.largestEccentricity = std::max(t.largestEccentricity, e);
      if (!keep) continue;
      t.y.push_back(x[0]);
      t.z.push_back(x[1]);
      t.eccentricity.push_back(e);
      for (std::size_t i = 2; i < j.equations.size(); ++i)
        t.own[i - 2].push_back(j.offset[Eigen::Index(i)] + s.u[j.equations[i]]);
    }
  };
  trackJournals(true);
  for (const PlacedRub& r : system.rubs()) {
    RubTrack t;
    t.name = r.rub->name;
    t.clearance = r.rub->clearance;
    out.rubs.push_back(std::move(t));
  }
  // Each rub's contact at the state `films` was taken at, at the end of a step of `stepTime`
  // (0 at the start): contact time and energy by the step, the rest at the samples.
  std::vector<RubForce> lastRubs = films.rubs;
  const auto trackRubs = [&](bool keep, double stepTime) {
    for (std::size_t k = 0; k < out.rubs.size(); ++k) {
      const PlacedRub& r = system.rubs()[k];
      const RubForce& f = films.rubs[k];
      RubTrack& t = out.rubs[k];
      if (f.touching()) {
        t.contactTime += stepTime;
        if (t.firstContact < 0) t.firstContact = now.t;
      }
      t.peakNormal = std::max(t.peakNormal, f.normal);
      t.peakTorque = std::max(t.peakTorque, std::abs(f.torque));
      t.frictionWork += stepTime / 2 * (lastRubs[k].frictionPower + f.frictionPower);
      t.dampingWork += stepTime / 2 * (lastRubs[k].dampingPower + f.dampingPower);
      if (!keep) continue;
      t.radial.push_back(std::hypot(s.u[r.y], s.u[r.z]));
      t.normal.push_back(f.normal);
      t.friction.push_back(r.rub->radius > 0 ? f.torque / r.rub->radius : 0);
      t.torque.push_back(f.torque);
    }
    lastRubs = films.rubs;
  };
  trackRubs(true, 0);
  Eigen::VectorXd residual =
      now.f + films.force - now.C * s.v - now.K * s.u - system.gyroscopicForce(now, s);

  const auto lateralStep = [&](const Instant& next) {
    StepOutcome step;
    step.damping = next.C + next.speed * rotor.gyroscopic();
    step.stiffness = next.K + next.acceleration * rotor.gyroscopic();
    const SparseMatrix& damping = step.damping;
    const SparseMatrix& stiffness = step.stiffness;
    const SparseMatrix S =
        rotor.mass() + (a1 * rule.gamma * dt) * damping + (a1 * rule.beta * dt * dt) * stiffness;
    Eigen::VectorXd uPredicted, vPredicted;
    rule.predict(s, uPredicted, vPredicted);
    Eigen::VectorXd a = Eigen::VectorXd::Zero(s.u.size()), u = uPredicted, v = vPredicted;
    out.time.assembly += clock.lap();
    // Newton's tangent is refactorised only when the last correction did not shrink tenfold
    // under the factor in hand (modified Newton): within a step the films' slopes move little,
    // so one factor usually carries every iteration, converging to the same tolerance.
    double lastCorrection = 0;
    bool refactor = true;
    for (int iteration = 1;; ++iteration) {
      try {
        step.films = system.films(u, v, next.speed);
      } catch (const JournalLeftClearance& e) {
        std::ostringstream msg;
        msg << "run-up at t = " << next.t << " s (" << next.speed * 30 / std::numbers::pi
            << " rpm), " << e.what();
        throw JournalLeftClearance(msg.str());
      }
      if (refactor) {
        SparseMatrix tangent = S;
        system.addTangents(tangent, step.films, a1 * rule.beta * dt * dt, a1 * rule.gamma * dt);
        if (!factor.factorize(tangent)) {
          std::ostringstream msg;
          msg << "run-up: the effective matrix M + gamma dt C + beta dt^2 K is singular at t = "
              << next.t << " s (rcond = " << factor.rcond()
              << "): some free dof has neither mass nor stiffness";
          throw SolveError(msg.str());
        }
        out.time.factor += clock.lap();
      }
      const Eigen::VectorXd rhs = a1 * (next.f + step.films.force - damping * v - stiffness * u) -
                                  rule.alpha * residual - rotor.mass() * a;
      const Eigen::VectorXd da = factor.solve(rhs);
      a += da;
      u = uPredicted + (rule.beta * dt * dt) * a;
      v = vPredicted + (rule.gamma * dt) * a;
      step.iterations = iteration;
      if (!nonlinear) break;  // linear: the one solve is exact
      const double correction = (rule.beta * dt * dt) * da.lpNorm<Eigen::Infinity>();
      if (correction <= tolerance) break;
      refactor = iteration > 1 && correction > 0.1 * lastCorrection;
      lastCorrection = correction;
      if (iteration == kMostNewtonIterations) {
        std::ostringstream msg;
        msg << "run-up: Newton's iterations on the journal films did not converge in "
            << kMostNewtonIterations << " iterations at t = " << next.t << " s (try a smaller dt)";
        throw SolveError(msg.str());
      }
    }
    step.state = s;
    rule.correct(step.state, uPredicted, vPredicted, a);
    step.state.t = next.t;  // the step's own time, free of the sum's round-off
    if (nonlinear) step.films = system.films(step.state.u, step.state.v, next.speed);
    out.time.solve += clock.lap();
    return step;
  };

  for (int step = 1; step <= out.steps; ++step) {
    const double t = step * dt;
    Instant next;
    StepOutcome outcome;
    if (!drive) {
      next = system.at(t, source.prescribed(t));
      outcome = lateralStep(next);
    } else {
      // The speed by the trapezoid rule, the angle by the average acceleration rule, from the
      // torque balance at t_n+1; the unbalance torque from the lateral step, iterated to a fixed
      // point (one pass without unbalance).
      const auto spinOf = [&](double acceleration) {
        return Spin{
            spin.speed + dt / 2 * (spin.acceleration + acceleration), acceleration,
            spin.angle + dt * spin.speed + dt * dt / 4 * (spin.acceleration + acceleration)};
      };
      double acceleration = balance(t, spin.speed, spin.acceleration, dt, load);
      for (int pass = 0;; ++pass) {
        next = system.at(t, spinOf(acceleration));
        outcome = lateralStep(next);
        if (o.unbalance.empty() && !nonlinear) break;
        if (!o.unbalance.empty())
          unbalanceTorque = system.unbalanceTorque(outcome.state.a, next.angle);
        load = loadOf(outcome.films, next.speed);
        const double settledAcceleration = balance(t, spin.speed, spin.acceleration, dt, load);
        if (settled(settledAcceleration, acceleration, t, next.speed)) break;
        if (pass == 50)
          throw SolveError(
              "run-up: the drive's speed and the rotor's motion did not settle in "
              "a step at t = " +
              std::to_string(t) + " s");
        acceleration = settledAcceleration;
      }
      spin = {next.speed, next.acceleration, next.angle};
    }
    out.newtonIterations += outcome.iterations;
    out.mostNewtonIterations = std::max(out.mostNewtonIterations, outcome.iterations);
    s = std::move(outcome.state);
    films = std::move(outcome.films);
    residual = next.f + films.force - outcome.damping * s.v - outcome.stiffness * s.u;
    now = std::move(next);
    energy.advance(now, s);
    const bool keep = step % o.sampleEvery == 0 || step == out.steps;
    sample(keep);
    trackJournals(keep);
    trackRubs(keep, dt);
    out.time.solve += clock.lap();
  }

  for (std::size_t k = 0; k < recorded.size(); ++k) {
    RunUpHistory& h = out.histories[k];
    h.revolutions = trackers[k].amplitudes();
    const auto& amp = h.revolutions.amplitude;
    if (amp.empty()) continue;
    const std::size_t peak = std::size_t(std::max_element(amp.begin(), amp.end()) - amp.begin());
    h.peakAmplitude = amp[peak];
    h.speedAtPeak = h.revolutions.speed[peak];
    h.timeAtPeak = h.revolutions.time[peak];
  }
  out.factorizations = factor.factorizations();
  out.size = rotor.systemSize(factor.factorEntries());
  out.time.total = total.lap();
  return out;
}

}  // namespace

RunUpResult solveRunUp(const Model& model, const SpeedProfile& profile, const RunUpOptions& o) {
  SpinSource source;
  source.profile = &profile;
  return runUp(model, source, o);
}

RunUpResult solveRunUp(const Model& model, const SpeedDrive& drive, const RunUpOptions& o) {
  if (!(drive.duration > 0) || !std::isfinite(drive.duration))
    throw std::invalid_argument("run-up: a driven run needs a positive duration");
  if (!(drive.startSpeed >= 0))
    throw std::invalid_argument("run-up: a driven run starts at a speed >= 0");
  SpinSource source;
  source.drive = &drive;
  return runUp(model, source, o);
}

std::optional<std::pair<double, double>> JournalTrack::ownRange(std::size_t k) const {
  const std::vector<double>& values = own.at(k);
  if (values.empty()) return std::nullopt;
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return std::pair{*low, *high};
}

}  // namespace beamrotor
