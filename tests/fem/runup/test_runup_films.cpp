// Run-up with journal bearings acting by their nonlinear film force (fem/runup/JournalFilm.hpp,
// elements/ShortJournalFilm.hpp) against the linear run on the same bearings' coefficients:
//  - at the film's own static equilibrium at a constant speed the rotor stays there (the
//    equilibrium from Ocvirk's Sommerfeld number, the force by quadrature of the same film);
//  - a small unbalance: the nonlinear orbit differs from the linear one at second order in the
//    amplitude (halving the unbalance quarters the difference);
//  - above the linear onset of instability (oil whip) the linear orbit grows without bound
//    while the nonlinear one settles on a limit cycle inside the clearance.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/ShortJournalFilm.hpp"
#include "fem/runup/RunUp.hpp"
#include "tests/fem/runup/FilmRunUpSupport.hpp"

using namespace beamrotor;

namespace {

/// A Jeffcott rotor on one short journal bearing: a disk (20 kg) on a shaft spring (1e6 N/m,
/// omega_n = 224 rad/s on a rigid bearing) to the journal (0.5 kg) in a bearing of D 50 mm,
/// L 20 mm, c 50 um, mu 0.02 Pa s carrying 200 N along -y. The bearing element holds the short
/// bearing's coefficients at `speed` (the linear run's; the nonlinear run takes them out).
struct FilmRotor {
  PlainJournal journal{0.05, 0.02, 50e-6, 0.02, 200};
  double speed;
  Model model;
  int disk = -1, node = -1, bearing = -1;
  explicit FilmRotor(double spin, double diskDamping = 0) : speed(spin) {
    const test::FilmJeffcott r =
        test::buildFilmJeffcott(model, shortBearingCoefficients(journal, speed), diskDamping);
    disk = r.disk, node = r.journal, bearing = r.bearing;
  }
  RunUpOptions options(double dt, double me, bool nonlinear) const {
    std::shared_ptr<const JournalFilm> film;
    if (nonlinear) film = std::make_shared<ShortJournalFilm>(journal);
    return test::filmRunUpOptions(disk, node, bearing, dt, me, film, {-journal.load, 0});
  }
};

}  // namespace

TEST_SUITE("run-up on journal films") {
  TEST_CASE("at the film's static equilibrium at constant speed the rotor stays there") {
    const FilmRotor rotor(300);
    const SpeedProfile constant = SpeedProfile::ramp(300, 300, 0.2);
    const RunUpResult r = solveRunUp(rotor.model, constant, rotor.options(1e-4, 0, true));
    // The film's force at the equilibrium balances the load to ~1e-13 W; the response to that
    // residue is ~1e-13 W / k_bearing ~ 1e-18 m. Allowed: 1e-12 of the clearance.
    const double c = rotor.journal.clearance;
    CHECK(test::largestOrbitRadius(r.histories[0]) < 1e-12 * c);
    CHECK(test::largestOrbitRadius(r.histories[1]) < 1e-12 * c);
    REQUIRE(r.journals.size() == 1);
    const double eps = eccentricityRatio(rotor.journal, 300);
    CHECK(r.journals[0].startEccentricity == doctest::Approx(eps).epsilon(1e-14));
    CHECK(r.journals[0].largestEccentricity == doctest::Approx(eps).epsilon(1e-12));
    MESSAGE("equilibrium: disk " << test::largestOrbitRadius(r.histories[0]) << " m, eps " << eps
                                 << ", Newton " << r.newtonIterations << " over " << r.steps
                                 << " steps, at most " << r.mostNewtonIterations);
  }

  TEST_CASE("a small unbalance: the films' difference from the linear run is of second order") {
    const FilmRotor rotor(300);
    const SpeedProfile constant = SpeedProfile::ramp(300, 300, 0.3);
    std::vector<double> differences;
    for (double me : {2e-5, 1e-5, 0.5e-5}) {
      const RunUpResult linear = solveRunUp(rotor.model, constant, rotor.options(1e-4, me, false));
      const RunUpResult films = solveRunUp(rotor.model, constant, rotor.options(1e-4, me, true));
      const double d = test::largestDiskDifference(linear, films);
      MESSAGE("me " << me << ": largest disk radius " << test::largestOrbitRadius(linear.histories[0])
                    << " m, difference " << d << " m, Newton at most "
                    << films.mostNewtonIterations);
      differences.push_back(d);
    }
    // Measured 4.005 and 4.003: the next order (the cube of the amplitude) shifts the ratio by
    // about the amplitude's share of the clearance (~2 %, 1 %) times a small factor.
    for (std::size_t k = 1; k < differences.size(); ++k) {
      MESSAGE("ratio " << differences[k - 1] / differences[k]);
      CHECK(differences[k - 1] / differences[k] == doctest::Approx(4).epsilon(0.01));
    }
  }
}

TEST_SUITE("run-up on journal films") {
  TEST_CASE("oil whip: the linear orbit grows, the film's settles on a limit cycle") {
    // With a damper of 180 N s/m at the disk (2 % of the shaft mode's critical damping) the
    // linear rotor loses stability near 520 rad/s, whirling forward at 212 rad/s (the
    // eigenvalues of the coefficients' model, measured while writing this test). At 700 rad/s
    // the whirl grows from the unbalance's small orbit; the films' stiffening stops it
    // (Muszynska, Rotordynamics, 2005, ch. 4: oil whip, a self-excited whirl locked to the
    // rotor's first natural frequency, near sqrt(k / m) = 224 rad/s here, bounded by the film).
    const FilmRotor rotor(700, 180);
    const SpeedProfile constant = SpeedProfile::ramp(700, 700, 10);
    const double dt = 2e-4, me = 2e-4;  // 145 steps a whip period; a 10 um seed orbit
    const RunUpResult films = solveRunUp(rotor.model, constant, rotor.options(dt, me, true));
    const RunUpResult linear = solveRunUp(rotor.model, constant, rotor.options(dt, me, false));
    const std::size_t n = films.times.size(), quarter = n / 4;
    // The largest disk radius over each quarter of the run.
    auto quarterPeaks = [&](const RunUpHistory& h) {
      std::vector<double> peaks;
      for (std::size_t q = 0; q < 4; ++q) {
        double r = 0;
        for (std::size_t i = q * quarter; i < (q + 1) * quarter; ++i)
          r = std::max(r, std::hypot(h.uy[i], h.uz[i]));
        peaks.push_back(r);
      }
      return peaks;
    };
    const std::vector<double> f = quarterPeaks(films.histories[0]);
    const std::vector<double> l = quarterPeaks(linear.histories[0]);
    MESSAGE("disk peaks by quarter, films: " << f[0] << " " << f[1] << " " << f[2] << " " << f[3]
                                             << "; linear: " << l[0] << " " << l[1] << " " << l[2]
                                             << " " << l[3]);
    MESSAGE("journal eccentricity at most " << films.journals[0].largestEccentricity << ", Newton "
                                            << films.newtonIterations << " over " << films.steps
                                            << ", at most " << films.mostNewtonIterations);
    // Whirl frequency of the last quarter: the disk's angle advances by 2 pi a whirl.
    const RunUpHistory& h = films.histories[0];
    double turned = 0;
    for (std::size_t i = 3 * quarter + 1; i < n; ++i)
      turned += std::remainder(std::atan2(h.uz[i], h.uy[i]) - std::atan2(h.uz[i - 1], h.uy[i - 1]),
                               2 * std::numbers::pi);
    const double whirl = turned / (films.times[n - 1] - films.times[3 * quarter]);
    MESSAGE("whirl " << whirl << " rad/s, " << whirl / 700 << " of the spin");
    // The linear orbit keeps growing (about 4.5 times a second); the film's has stopped: its
    // last two quarters peak within 10 % of each other, the journal well inside the clearance.
    CHECK(l[3] > 5 * l[2]);
    CHECK(f[3] < 1.1 * f[2]);
    CHECK(f[3] < l[3] / 10);
    CHECK(films.journals[0].largestEccentricity < 0.9);
    // Oil whip: a forward whirl locked near the first natural frequency sqrt(k / m) = 224
    // rad/s, far below half the spin (the measured 216 rad/s is the mode on the films).
    CHECK(whirl / std::sqrt(1e6 / 20) == doctest::Approx(1).epsilon(0.05));
    CHECK(whirl < 0.4 * 700);
  }
}

TEST_SUITE("run-up driven by a torque") {
  /// A free rotor: a disk (10 kg, Jp 0.5 kg m^2) on an isotropic bearing, no unbalance.
  struct FreeRotor {
    Model model;
    int node = -1;
    FreeRotor() {
      node = model.addNode({0, 0, 0});
      model.add<PointInertia>(node, DofSet{Dof::uy, Dof::uz}, 10.0);
      model.add<Bearing>(node, BearingCoefficients::isotropic(1e6, 100));
    }
    RunUpOptions options(double dt) const {
      RunUpOptions o;
      o.timeStep = dt;
      o.nodes = {node};
      return o;
    }
  };

  TEST_CASE("a constant torque on a free rotor: Omega = Omega_0 + T t / J exactly") {
    const FreeRotor rotor;
    SpeedDrive drive;
    drive.torque = DriveTorque::constant(20);
    drive.inertia = 0.5;
    drive.startSpeed = 10;
    drive.duration = 2;
    const RunUpResult r = solveRunUp(rotor.model, drive, rotor.options(1e-3));
    REQUIRE(r.driven);
    // The trapezoid rule integrates a constant acceleration exactly, and the average
    // acceleration rule the angle: both to round-off of the sums over 2000 steps.
    double speedError = 0, angleError = 0;
    for (std::size_t i = 0; i < r.times.size(); ++i) {
      const double t = r.times[i];
      speedError = std::max(speedError, std::abs(r.speed[i] - (10 + 40 * t)));
      angleError = std::max(angleError, std::abs(r.angle[i] - (10 * t + 20 * t * t)));
    }
    MESSAGE("constant torque: speed error " << speedError << " rad/s, angle error " << angleError
                                            << " rad");
    CHECK(speedError < 1e-11 * 90);
    CHECK(angleError < 1e-11 * 100);
    CHECK(r.driveTorque.back() == doctest::Approx(20).epsilon(1e-15));
  }

  TEST_CASE("a linear motor curve: the exponential approach to the synchronous speed") {
    const FreeRotor rotor;
    // T = T0 (1 - Omega / Omega_s): J Omega' = T0 (1 - Omega / Omega_s), so
    // Omega = Omega_s + (Omega_0 - Omega_s) exp(-t / tau), tau = J Omega_s / T0 = 0.25 s.
    const double T0 = 60, Ws = 300, J = 0.05, W0 = 20, tau = J * Ws / T0;
    std::vector<double> errors;
    for (double dt : {4e-3, 2e-3, 1e-3}) {
      SpeedDrive drive;
      drive.torque = DriveTorque::againstSpeed({0, Ws}, {T0, 0});
      drive.inertia = J;
      drive.startSpeed = W0;
      drive.duration = 1;
      const RunUpResult r = solveRunUp(rotor.model, drive, rotor.options(dt));
      double e = 0;
      for (std::size_t i = 0; i < r.times.size(); ++i)
        e = std::max(e, std::abs(r.speed[i] - (Ws + (W0 - Ws) * std::exp(-r.times[i] / tau))));
      errors.push_back(e);
      MESSAGE("motor curve, dt " << dt << ": largest speed error " << e << " rad/s");
    }
    // The trapezoid rule is second order: halving dt quarters the error (the rate within 1 %
    // at these steps, dt / tau <= 0.016).
    for (std::size_t k = 1; k < errors.size(); ++k)
      CHECK(errors[k - 1] / errors[k] == doctest::Approx(4).epsilon(0.01));
    CHECK(errors.back() < 1e-4 * Ws);
  }

  TEST_CASE("the films' drag on a driven speed: the speed a constant torque settles at") {
    // The film rotor's journal (D 50 mm, L 20 mm, c 50 um, mu 0.02 Pa s, 200 N) driven by a
    // constant torque on J = 5e-5 kg m^2 from 200 rad/s. At each speed the journal sits at
    // Ocvirk's eccentricity eps(Omega) and the film's drag is
    //   T_d(Omega) = 2 pi mu Omega R^3 L / (c sqrt(1 - eps^2)) + e W sin(phi) / 2;
    // the speed settles where T = T_d(Omega_s), found here by bisection on the closed form.
    const FilmRotor rotor(300, 2000);  // the disk damped: the lateral motion settles too
    const PlainJournal& b = rotor.journal;
    const double R = b.diameter / 2, torque = 0.5;
    const auto drag = [&](double w) {
      const double eps = eccentricityRatio(b, w);
      const double phi = std::atan(std::numbers::pi * std::sqrt(1 - eps * eps) / (4 * eps));
      return 2 * std::numbers::pi * b.viscosity * w * R * R * R * b.length /
                 (b.clearance * std::sqrt(1 - eps * eps)) +
             eps * b.clearance * b.load * std::sin(phi) / 2;
    };
    double lo = 10, hi = 5000;
    for (int k = 0; k < 200; ++k) (drag((lo + hi) / 2) < torque ? lo : hi) = (lo + hi) / 2;
    const double steady = (lo + hi) / 2;
    SpeedDrive drive;
    drive.torque = DriveTorque::constant(torque);
    drive.inertia = 5e-5;
    drive.startSpeed = 200;
    drive.duration = 1.5;
    RunUpOptions o = rotor.options(2e-4, 0, true);
    o.start = RunUpStart::rest;
    const RunUpResult r = solveRunUp(rotor.model, drive, o);
    REQUIRE(r.filmTorque.size() == r.times.size());
    // tau = J / (dT_d/dOmega) ~ 0.05 s: after 1.5 s the speed is within e^-30 of its
    // limit, which the trapezoid rule keeps exactly (a fixed point of the step); the film
    // carries its load to ~1e-12 (quasi-static): 1e-6.
    CHECK(r.speed.back() == doctest::Approx(steady).epsilon(1e-6));
    CHECK(r.filmTorque.back() == doctest::Approx(torque).epsilon(1e-6));
    MESSAGE("drag: steady speed " << r.speed.back() << " rad/s against " << steady
                                  << " (closed form), film torque " << r.filmTorque.back()
                                  << " N m, Newton at most " << r.mostNewtonIterations);
  }
}
