// Run-up with a tilting-pad bearing acting by its pads' nonlinear films, each pad's tilt a dof
// (elements/TiltingPadJournalFilm.hpp), against the LINEAR run of the same rotor with its pads'
// tilts as dofs (elements/TiltingPadFilm.hpp: each pad's film coefficients at the bearing's
// equilibrium, the model the linear analyses condense at whirl = spin):
//  - at the pads' equilibrium at a constant speed the rotor and the pads stay there;
//  - a small unbalance: the nonlinear orbit differs from the linear one at second order in the
//    amplitude (halving the unbalance quarters the difference).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "elements/TiltingPadJournalFilm.hpp"
#include "fem/runup/RunUp.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"
#include "tests/fem/runup/FilmRunUpSupport.hpp"

using namespace beamrotor;

namespace {

/// The tests' bearing carrying 1000 N: every pad loaded (at the tests' 5000 N the two upper
/// pads sit at m + rho = -0.016, where they switch off: a kink in the force).
PlainJournal lightJournal() {
  PlainJournal j = test::tiltingPadTestJournal();
  j.load = 1000;
  return j;
}

/// The model this run-up replaced, for the record of what the tests tell apart: each massless
/// pad held on its film's tilt root for the journal's state (its moment zero, its film
/// squeezed by the journal's velocity towards the pivot, the pad following the journal across
/// its pivot line: s' = 0), the pads' tilts condensed by the implicit-function theorem. Built
/// on the tilt-dof film: the same pad films.
class TiltRootFilm : public JournalFilm {
 public:
  TiltRootFilm(const PlainJournal& j, const TiltingPads& pads, const ReynoldsGrid& grid)
      : film_(j, pads, grid, 0.0), radius_(j.diameter / 2), clearance_(j.clearance) {
    for (int k = 0; k < pads.count; ++k) {
      const double pivot = std::numbers::pi + (pads.loadOnPad ? 0 : std::numbers::pi / pads.count) +
                           2 * std::numbers::pi * k / pads.count;
      across_.push_back({-std::sin(pivot), std::cos(pivot)});
    }
  }
  FilmForce at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
               double speed) const override {
    const Eigen::Index n = Eigen::Index(across_.size());
    Eigen::MatrixXd T(n, 2);  // delta' = T u': the pads follow the journal across
    for (Eigen::Index k = 0; k < n; ++k) T.row(k) = across_[std::size_t(k)].transpose() / radius_;
    Eigen::VectorXd x(n + 2), v(n + 2);
    x << position, tilts_;
    v << velocity, T * velocity;
    FilmLoad f;
    for (int iteration = 0;; ++iteration) {
      f = film_.loadAt(x, v, speed);
      const Eigen::VectorXd step =
          f.stiffness.bottomRightCorner(n, n).diagonal().cwiseInverse().cwiseProduct(f.force.tail(n));
      x.tail(n) += step;
      if (step.cwiseAbs().maxCoeff() < 1e-13 * clearance_ / radius_) break;
      REQUIRE(iteration < 30);
    }
    f = film_.loadAt(x, v, speed);
    tilts_ = x.tail(n);
    const Eigen::MatrixXd Kpp = f.stiffness.bottomRightCorner(n, n);
    const Eigen::MatrixXd Kjp = f.stiffness.topRightCorner(2, n), Kpj = f.stiffness.bottomLeftCorner(n, 2);
    const Eigen::MatrixXd Cjp = f.damping.topRightCorner(2, n), Cpj = f.damping.bottomLeftCorner(n, 2);
    const Eigen::MatrixXd Cpp = f.damping.bottomRightCorner(n, n);
    const Eigen::MatrixXd KppInverse = Kpp.inverse();
    FilmForce out;
    out.force = f.force.head<2>();
    out.stiffness = f.stiffness.topLeftCorner<2, 2>() - Kjp * KppInverse * Kpj;
    out.damping = f.damping.topLeftCorner<2, 2>() + Cjp * T - Kjp * KppInverse * (Cpj + Cpp * T);
    return out;
  }
  Eigen::Vector2d equilibrium(const Eigen::Vector2d& load, double speed) const override {
    const Eigen::VectorXd rest = film_.restState(load, speed);
    tilts_ = rest.tail(rest.size() - 2);
    return rest.head<2>();
  }
  double dragTorque(const Eigen::Vector2d&, const Eigen::Vector2d&, double) const override {
    return 0;
  }
  double clearance() const override { return clearance_; }

 private:
  TiltingPadJournalFilm film_;
  double radius_, clearance_;
  std::vector<Eigen::Vector2d> across_;  ///< t_k
  mutable Eigen::VectorXd tilts_;
};


/// A Jeffcott rotor on one tilting-pad bearing: a disk (100 kg) on a shaft spring (5e7 N/m) to
/// the journal (5 kg) in the tests' four-pad bearing (D 100 mm, L 50 mm, c 100 um, preload 0.3,
/// 80 deg pads, load between pads, 1000 N along -y), each pad's film on 16 x 4 cells (coarse,
/// to keep the test short: the film and its coefficients share any grid), each pad's tilt a
/// dof (massless, or of polar moment `inertia` about its pivot) holding its film's
/// coefficients at the bearing's equilibrium at `speed` (the linear run's; the nonlinear run
/// takes them out and keeps the inertia).
struct PadFilmRotor {
  PlainJournal journal = lightJournal();
  TiltingPads pads = test::fourPadsBetween();
  ReynoldsGrid grid{16, 4};
  double speed;
  Model model;
  int disk = -1, node = -1;
  std::vector<int> padElements;
  std::vector<NodeDof> padDofs;
  explicit PadFilmRotor(double spin, double inertia = 0) : speed(spin) {
    disk = model.addNode({0, 0, 0});
    node = model.addNode({0.1, 0, 0});
    model.add<PointInertia>(disk, DofSet{Dof::uy, Dof::uz}, 100.0);
    model.add<PointInertia>(node, DofSet{Dof::uy, Dof::uz}, 5.0);
    for (Dof d : {Dof::uy, Dof::uz}) model.add<Spring>(NodeDof{disk, d}, NodeDof{node, d}, 5e7);
    const auto points = std::make_shared<const std::vector<TiltingPadPoint>>(
        1, tiltingPadPoint(journal, pads, speed, grid));
    for (int pad = 0; pad < pads.count; ++pad) {
      const int tilt = model.addNode({0.1, 0, 0});
      model.add<TiltingPadFilm>(node, tilt, points, pad, 0.0, inertia);
      padElements.push_back(int(model.elements().size()) - 1);
      padDofs.push_back({tilt, Dof::rx});
    }
  }
  Eigen::Vector2d load() const { return {-journal.load, 0}; }
  /// The same rotor with the tilt-root film on the journal alone (a Bearing element holding
  /// nothing in place of the pads).
  RunUpResult tiltRootRun(const SpeedProfile& profile, double dt, double me) const {
    Model root;
    const int d = root.addNode({0, 0, 0}), j = root.addNode({0.1, 0, 0});
    root.add<PointInertia>(d, DofSet{Dof::uy, Dof::uz}, 100.0);
    root.add<PointInertia>(j, DofSet{Dof::uy, Dof::uz}, 5.0);
    for (Dof dof : {Dof::uy, Dof::uz}) root.add<Spring>(NodeDof{d, dof}, NodeDof{j, dof}, 5e7);
    root.add<Bearing>(j, BearingCoefficients{});
    const int bearing = int(root.elements().size()) - 1;
    return solveRunUp(root, profile,
                      test::filmRunUpOptions(d, j, bearing, dt, me,
                                             std::make_shared<TiltRootFilm>(journal, pads, grid),
                                             load()));
  }
  RunUpOptions options(double dt, double me, bool nonlinear) const {
    RunUpOptions o = test::filmRunUpOptions(disk, node, -1, dt, me, nullptr, load());
    if (nonlinear) {
      NonlinearJournal j;
      j.name = "pads";
      j.node = node;
      j.film = std::make_shared<TiltingPadJournalFilm>(journal, pads, grid, 0.0);
      j.ownElements = padElements;
      j.ownDofs = padDofs;
      j.load = load();
      o.journals = {j};
    }
    return o;
  }
};

}  // namespace

TEST_SUITE("run-up on tilting-pad films") {
  TEST_CASE("at the pads' equilibrium at constant speed the rotor and its pads stay there") {
    const PadFilmRotor rotor(400);
    const SpeedProfile constant = SpeedProfile::ramp(400, 400, 0.02);
    const RunUpResult r = solveRunUp(rotor.model, constant, rotor.options(1e-4, 0, true));
    // The film carries the load at its equilibrium to 1e-11 W (the bearing's Newton) and each
    // pad's moment vanishes to its root's tolerance; the journal moves by that residue over
    // the film's stiffness, of order W / c: some 1e-11 c, at most 1e-9 c allowed.
    const double c = rotor.journal.clearance;
    MESSAGE("pads' equilibrium: disk " << test::largestOrbitRadius(r.histories[0])
                                       << " m, journal " << test::largestOrbitRadius(r.histories[1])
                                       << " m, Newton " << r.newtonIterations << " over "
                                       << r.steps << " steps, drag " << r.filmTorque.back()
                                       << " N m");
    CHECK(test::largestOrbitRadius(r.histories[0]) < 1e-9 * c);
    CHECK(test::largestOrbitRadius(r.histories[1]) < 1e-9 * c);
    REQUIRE(r.journals.size() == 1);
    const TiltingPadJournalFilm film(rotor.journal, rotor.pads, rotor.grid, 0.0);
    const Eigen::VectorXd rest = film.restState(rotor.load(), 400);
    CHECK(r.journals[0].startEccentricity ==
          doctest::Approx(rest.head<2>().norm() / c).epsilon(1e-14));
    // The pads stay at the bearing's own equilibrium tilts (tiltingPadPoint, the run's tracks
    // of the pads' dofs): to the same 1e-9 c over the radius.
    const TiltingPadPoint p = tiltingPadPoint(rotor.journal, rotor.pads, 400, rotor.grid);
    REQUIRE(r.journals[0].own.size() == 4);
    CHECK(r.journals[0].ownNames[3] == "pad4_tilt");
    for (std::size_t k = 0; k < 4; ++k)
      for (double tilt : r.journals[0].own[k])
        CHECK(std::abs(tilt - p.pads[k].tilt) < 1e-9 * c / (rotor.journal.diameter / 2));
    // The drag reported is the film's at its equilibrium (the run's last state is the first).
    CHECK(r.filmTorque.back() ==
          doctest::Approx(film.dragTorqueAt(
                              rest, film.loadAt(rest, Eigen::VectorXd::Zero(6), 400).force, 400))
              .epsilon(1e-9));
  }

  TEST_CASE("a small unbalance: the pads' films differ from the linear run at second order") {
    // Massless pads, and pads of 2e-4 kg m^2 about their pivots (each its own mass in both
    // runs; the nonlinear run takes only the films' K and C out).
    for (double inertia : {0.0, 2e-4}) {
    CAPTURE(inertia);
    const PadFilmRotor rotor(400, inertia);
    const SpeedProfile constant = SpeedProfile::ramp(400, 400, 0.1);
    std::vector<double> differences;
    for (double me : {2.5e-4, 1.25e-4, 0.625e-4}) {
      const RunUpResult linear = solveRunUp(rotor.model, constant, rotor.options(1e-4, me, false));
      const RunUpResult films = solveRunUp(rotor.model, constant, rotor.options(1e-4, me, true));
      const double d = test::largestDiskDifference(linear, films);
      MESSAGE("me " << me << ": largest disk radius "
                    << test::largestOrbitRadius(linear.histories[0]) << " m, journal eps up to "
                    << films.journals[0].largestEccentricity << ", difference " << d
                    << " m, Newton " << films.newtonIterations << " over " << films.steps
                    << " steps, at most " << films.mostNewtonIterations << ", "
                    << films.time.total << " s");
      differences.push_back(d);
    }
    // Second order in the unbalance: ratio 4 when it halves (a model wrong at first order, as
    // each pad held on its film's tilt root, gives 2: docs/runup.md). 1 % allowed: the next
    // order's share shrinks with the amplitude.
    for (std::size_t k = 1; k < differences.size(); ++k) {
      MESSAGE("ratio " << differences[k - 1] / differences[k]);
      CHECK(differences[k - 1] / differences[k] == doctest::Approx(4).epsilon(0.01));
    }
    }
  }

  TEST_CASE("the pads' inertia enters the film run as it enters the linear one") {
    // The same unbalance on pads of 5e-3 kg m^2 and on massless pads: the linear runs differ by
    // the inertia's share (1.36e-8 m on a 5.7e-7 m orbit), and the film runs by the same up to
    // their own second-order parts (1.5e-9 m each at this unbalance, the test above), which
    // mostly cancel: measured 0.4 %, 5 % allowed.
    const SpeedProfile constant = SpeedProfile::ramp(400, 400, 0.1);
    const PadFilmRotor massless(400), heavy(400, 5e-3);
    const double me = 0.625e-4;
    const RunUpResult linear0 = solveRunUp(massless.model, constant, massless.options(1e-4, me, false));
    const RunUpResult linear1 = solveRunUp(heavy.model, constant, heavy.options(1e-4, me, false));
    const RunUpResult films0 = solveRunUp(massless.model, constant, massless.options(1e-4, me, true));
    const RunUpResult films1 = solveRunUp(heavy.model, constant, heavy.options(1e-4, me, true));
    const double linearShare = test::largestDiskDifference(linear0, linear1);
    const double filmShare = test::largestDiskDifference(films0, films1);
    MESSAGE("inertia's share: linear " << linearShare << " m, films " << filmShare << " m, orbit "
                                       << test::largestOrbitRadius(linear0.histories[0]) << " m");
    CHECK(linearShare > 0);
    CHECK(filmShare == doctest::Approx(linearShare).epsilon(0.05));
  }

  TEST_CASE("the pads held on their films' tilt roots differ from the linear run at first order") {
    // The model h-tpfilm proposed (TiltRootFilm above): its linearisation is the static
    // stiffness and a following damping, not the pads' films with their tilts free, so its
    // difference from the linear run with the pads' tilts as dofs halves with the unbalance
    // (ratio 2), where the tilt-dof film's quarters (the test above): the test tells them apart.
    const PadFilmRotor rotor(400);
    const SpeedProfile constant = SpeedProfile::ramp(400, 400, 0.1);
    std::vector<double> differences;
    for (double me : {2.5e-4, 1.25e-4}) {
      const RunUpResult linear = solveRunUp(rotor.model, constant, rotor.options(1e-4, me, false));
      const RunUpResult root = rotor.tiltRootRun(constant, 1e-4, me);
      differences.push_back(test::largestDiskDifference(linear, root));
      MESSAGE("tilt roots, me " << me << ": difference " << differences.back() << " m of "
                                << test::largestOrbitRadius(linear.histories[0]) << " m");
    }
    const double ratio = differences[0] / differences[1];
    MESSAGE("tilt roots: ratio " << ratio);
    // First order: 2 to the next order's share (measured below); 5 % allowed.
    CHECK(ratio == doctest::Approx(2).epsilon(0.05));
  }
}
