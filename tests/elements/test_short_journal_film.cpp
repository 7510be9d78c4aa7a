// The short bearing's nonlinear film force (elements/ShortJournalFilm.hpp) against the closed
// forms of the same theory: the static load and attitude (Ocvirk's Sommerfeld number), the
// eight linear coefficients (elements/PlainJournalBearing.cpp's formulas), the centred
// journal's squeeze and cross-coupling (elements/ConcentricJournal.cpp), and its own
// derivatives by central differences away from equilibrium.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "elements/ConcentricJournal.hpp"
#include "elements/ShortJournalFilm.hpp"

using namespace beamrotor;

namespace {

PlainJournal filmBearing() {
  // D 100 mm, L 40 mm (L/D 0.4), c 75 um, mu 0.018 Pa s, 4000 N.
  return {0.1, 0.04, 75e-6, 0.018, 4000};
}

}  // namespace

TEST_SUITE("short journal film") {
  TEST_CASE(
      "at its equilibrium the film carries the load, with the linear coefficients as slopes") {
    const PlainJournal b = filmBearing();
    const ShortJournalFilm film(b);
    for (double rpm : {500.0, 3000.0, 15000.0}) {
      for (double loadAngle : {0.0, 0.7}) {  // the load along -y, and turned by 0.7 rad
        const double speed = rpm * std::numbers::pi / 30;
        CAPTURE(rpm);
        CAPTURE(loadAngle);
        const Eigen::Vector2d load =
            -b.load * Eigen::Vector2d(std::cos(loadAngle), std::sin(loadAngle));
        const Eigen::Vector2d x0 = film.equilibrium(load, speed);
        const FilmForce f = film.at(x0, Eigen::Vector2d::Zero(), speed);
        // The eccentricity is bisected to the last bit and the quadrature is at round-off
        // (64 Gauss points on an analytic integrand): the balance holds to ~1e-13 of W.
        CHECK((f.force + load).norm() < 1e-12 * b.load);
        if (loadAngle != 0) continue;
        // Along -y the slopes are the closed-form coefficients (their own round-off ~1e-14).
        const BearingCoefficients k = shortBearingCoefficients(b, speed);
        const double ks = b.load / b.clearance, cs = ks / speed;
        CHECK(std::abs(f.stiffness(0, 0) - k.kyy) < 1e-11 * ks);
        CHECK(std::abs(f.stiffness(0, 1) - k.kyz) < 1e-11 * ks);
        CHECK(std::abs(f.stiffness(1, 0) - k.kzy) < 1e-11 * ks);
        CHECK(std::abs(f.stiffness(1, 1) - k.kzz) < 1e-11 * ks);
        CHECK(std::abs(f.damping(0, 0) - k.cyy) < 1e-11 * cs);
        CHECK(std::abs(f.damping(0, 1) - k.cyz) < 1e-11 * cs);
        CHECK(std::abs(f.damping(1, 0) - k.czy) < 1e-11 * cs);
        CHECK(std::abs(f.damping(1, 1) - k.czz) < 1e-11 * cs);
      }
    }
  }

  TEST_CASE("a centred journal: squeeze damping and the cross-coupling of half a film") {
    PlainJournal b = filmBearing();
    b.load = 0;
    const ShortJournalFilm film(b);
    const double speed = 300;
    const BearingCoefficients k = concentricJournalCoefficients(b, speed);
    // A small displacement along +y: to first order -k_zy y across and nothing along (the
    // force's next term is of order (y / c)^2 = 1e-14 relative).
    const double y = 1e-7 * b.clearance;
    const FilmForce f = film.at({y, 0}, {0, 0}, speed);
    CHECK(std::abs(f.force[0]) < 1e-6 * k.kyz * y);
    CHECK(f.force[1] == doctest::Approx(-k.kzy * y).epsilon(1e-6));
    // Pure squeeze along y with no spin: -c v, c = pi mu R L^3 / (2 c^3).
    const double v = 1e-3;
    const FilmForce s = film.at({0, 0}, {v, 0}, 0);
    CHECK(s.force[0] == doctest::Approx(-k.cyy * v).epsilon(1e-12));
    CHECK(std::abs(s.force[1]) < 1e-12 * k.cyy * v);
  }

  TEST_CASE("the derivatives away from equilibrium are the force's own") {
    const PlainJournal b = filmBearing();
    const ShortJournalFilm film(b);
    const double speed = 400, c = b.clearance;
    // An orbiting journal at eps 0.6 moving at 0.3 c Omega across and towards the wall.
    const Eigen::Vector2d x{-0.5 * c, 0.33 * c}, v{0.1 * c * speed, -0.25 * c * speed};
    const FilmForce f = film.at(x, v, speed);
    // Central differences with steps 1e-6 c (and 1e-6 c Omega): truncation ~1e-12 of the
    // scale, round-off ~1e-16 / 1e-6 = 1e-10; compared to 1e-7 of the largest entry.
    const double d = 1e-6 * c;
    const double scale = f.stiffness.cwiseAbs().maxCoeff(),
                 cscale = f.damping.cwiseAbs().maxCoeff();
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d e = Eigen::Vector2d::Zero();
      e[j] = d;
      const Eigen::Vector2d kj =
          -(film.at(x + e, v, speed).force - film.at(x - e, v, speed).force) / (2 * d);
      const Eigen::Vector2d cj =
          -(film.at(x, v + e * speed, speed).force - film.at(x, v - e * speed, speed).force) /
          (2 * d * speed);
      CAPTURE(j);
      CHECK((kj - f.stiffness.col(j)).norm() < 1e-7 * scale);
      CHECK((cj - f.damping.col(j)).norm() < 1e-7 * cscale);
    }
  }

  TEST_CASE("the film's drag torque: Petroff at eccentricity plus e W sin(phi) / 2") {
    // The short bearing's friction torque on the journal at its steady equilibrium (the form
    // of Hamrock, Fundamentals of Fluid Film Lubrication, ch. 13, for the short bearing):
    //   T = 2 pi mu Omega R^3 L / (c sqrt(1 - eps^2)) + e W sin(phi) / 2,
    // phi Ocvirk's attitude angle, tan(phi) = pi sqrt(1 - eps^2) / (4 eps).
    const PlainJournal b = filmBearing();
    const ShortJournalFilm film(b);
    const double R = b.diameter / 2;
    for (double rpm : {500.0, 3000.0, 15000.0}) {
      const double speed = rpm * std::numbers::pi / 30;
      const Eigen::Vector2d x0 = film.equilibrium({-b.load, 0}, speed);
      const FilmForce f = film.at(x0, Eigen::Vector2d::Zero(), speed);
      const double eps = eccentricityRatio(b, speed);
      const double phi = std::atan(std::numbers::pi * std::sqrt(1 - eps * eps) / (4 * eps));
      const double expected =
          2 * std::numbers::pi * b.viscosity * speed * R * R * R * b.length /
              (b.clearance * std::sqrt(1 - eps * eps)) +
          eps * b.clearance * b.load * std::sin(phi) / 2;
      // The film force carries W to 1e-12 and eps is bisected to the last bit: 1e-12.
      CAPTURE(rpm);
      CHECK(film.dragTorque(x0, f.force, speed) == doctest::Approx(expected).epsilon(1e-12));
      MESSAGE(rpm << " rpm: eps " << eps << ", drag " << film.dragTorque(x0, f.force, speed)
                  << " N m against " << expected);
    }
    // Centred (unloaded): Petroff's torque 2 pi mu Omega R^3 L / c.
    CHECK(film.dragTorque(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), 100) ==
          doctest::Approx(2 * std::numbers::pi * b.viscosity * 100 * R * R * R * b.length /
                          b.clearance)
              .epsilon(1e-15));
  }

  TEST_CASE("a journal at the wall is refused with a message, never NaN") {
    const ShortJournalFilm film(filmBearing());
    const double c = filmBearing().clearance;
    CHECK_THROWS_AS(film.at({0.8 * c, -0.61 * c}, {0, 0}, 300), JournalLeftClearance);
    CHECK_THROWS_WITH(film.at({1.5 * c, 0}, {0, 0}, 300),
                      doctest::Contains("left the bearing's clearance (eccentricity ratio 1.5"));
  }
}
