// Run-up with a tilting-pad bearing acting by its pads' nonlinear films
// (elements/TiltingPadJournalFilm.hpp) against the linear run on the same film's slopes at its
// equilibrium (the static stiffness and the pads' following damping, a Bearing element):
//  - at the pads' equilibrium at a constant speed the rotor stays there;
//  - a small unbalance: the nonlinear orbit differs from the linear one at second order in the
//    amplitude (halving the unbalance quarters the difference).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
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

/// A Jeffcott rotor on one tilting-pad bearing: a disk (100 kg) on a shaft spring (5e7 N/m) to
/// the journal (5 kg) in the tests' four-pad bearing (D 100 mm, L 50 mm, c 100 um, preload 0.3,
/// 80 deg pads, load between pads, 1000 N along -y), each pad's film on
/// 16 x 4 cells (coarse, to keep the test short: the film and its slopes share any grid). The
/// bearing element holds the film's slopes at its equilibrium at `speed` (the linear run's;
/// the nonlinear run takes them out).
struct PadFilmRotor {
  PlainJournal journal = lightJournal();
  TiltingPads pads = test::fourPadsBetween();
  ReynoldsGrid grid{16, 4};
  double speed;
  Model model;
  int disk = -1, node = -1, bearing = -1;
  std::shared_ptr<const TiltingPadJournalFilm> film;
  Eigen::Vector2d rest;  ///< the journal's equilibrium
  explicit PadFilmRotor(double spin) : speed(spin) {
    disk = model.addNode({0, 0, 0});
    node = model.addNode({0.1, 0, 0});
    model.add<PointInertia>(disk, DofSet{Dof::uy, Dof::uz}, 100.0);
    model.add<PointInertia>(node, DofSet{Dof::uy, Dof::uz}, 5.0);
    for (Dof d : {Dof::uy, Dof::uz}) model.add<Spring>(NodeDof{disk, d}, NodeDof{node, d}, 5e7);
    film = std::make_shared<TiltingPadJournalFilm>(journal, pads, grid, 0.0);
    rest = film->equilibrium(load(), speed);
    const FilmForce f = film->at(rest, Eigen::Vector2d::Zero(), speed);
    model.add<Bearing>(node, BearingCoefficients{f.stiffness(0, 0), f.stiffness(0, 1),
                                                 f.stiffness(1, 0), f.stiffness(1, 1),
                                                 f.damping(0, 0), f.damping(0, 1),
                                                 f.damping(1, 0), f.damping(1, 1)});
    bearing = int(model.elements().size()) - 1;
  }
  Eigen::Vector2d load() const { return {-journal.load, 0}; }
  RunUpOptions options(double dt, double me, bool nonlinear) const {
    std::shared_ptr<const JournalFilm> f;
    if (nonlinear) f = std::make_shared<TiltingPadJournalFilm>(journal, pads, grid, 0.0);
    return test::filmRunUpOptions(disk, node, bearing, dt, me, f, load());
  }
};

}  // namespace

TEST_SUITE("run-up on tilting-pad films") {
  TEST_CASE("at the pads' equilibrium at constant speed the rotor stays there") {
    const PadFilmRotor rotor(400);
    const SpeedProfile constant = SpeedProfile::ramp(400, 400, 0.02);
    const RunUpResult r = solveRunUp(rotor.model, constant, rotor.options(1e-4, 0, true));
    // The film carries the load at its equilibrium to 1e-12 W (the Newton's tolerance); the
    // journal moves by that residue over the film's stiffness, of order W / c: some 1e-12 c, at
    // most 1e-9 c allowed (measured 3e-18 m, 3e-14 c).
    const double c = rotor.journal.clearance;
    MESSAGE("pads' equilibrium: disk " << test::largestOrbitRadius(r.histories[0])
                                       << " m, journal " << test::largestOrbitRadius(r.histories[1])
                                       << " m, Newton " << r.newtonIterations << " over "
                                       << r.steps << " steps, drag " << r.filmTorque.back()
                                       << " N m");
    CHECK(test::largestOrbitRadius(r.histories[0]) < 1e-9 * c);
    CHECK(test::largestOrbitRadius(r.histories[1]) < 1e-9 * c);
    REQUIRE(r.journals.size() == 1);
    CHECK(r.journals[0].startEccentricity == doctest::Approx(rotor.rest.norm() / c).epsilon(1e-14));
    // The drag reported is the film's at its equilibrium (the run's last state is the first).
    CHECK(r.filmTorque.back() ==
          doctest::Approx(rotor.film->dragTorque(
                              rotor.rest, rotor.film->at(rotor.rest, {0, 0}, 400).force, 400))
              .epsilon(1e-9));
  }

  TEST_CASE("a small unbalance: the pads' films differ from the linear run at second order") {
    const PadFilmRotor rotor(400);
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
                    << " steps, at most " << films.mostNewtonIterations);
      differences.push_back(d);
    }
    // Second order in the unbalance: ratio 4 when it halves. Measured 3.978 and 3.989 (journal
    // orbits 0.011, 0.0036, 0.0018 of c about eps 0.25): the shortfall halves with the
    // amplitude, the next order's share (at eight and four times these unbalances 3.65 and
    // 3.88); 1 % allowed.
    for (std::size_t k = 1; k < differences.size(); ++k) {
      MESSAGE("ratio " << differences[k - 1] / differences[k]);
      CHECK(differences[k - 1] / differences[k] == doctest::Approx(4).epsilon(0.01));
    }
  }
}
