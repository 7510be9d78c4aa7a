// Static bearing loads of a rotor under gravity against statics by hand: a shaft with a disk
// on two bearings (moment balance), a shaft on three pinned bearings (two-span continuous
// beam) and on three elastic bearings (compatibility with spring supports), and the sag.
#include <doctest/doctest.h>

#include <cmath>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/GravityLoads.hpp"
#include "fem/solvers/Errors.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kGravityTest = 9.81;

/// A uniform steel shaft (D 50 mm) along x with a node at each of `stations` (m), meshed with
/// `perSpan` elements between consecutive stations.
struct StationShaft {
  std::vector<double> stations;
  int perSpan = 8;
  std::shared_ptr<const Section> section = steelCircle(0.05);
  std::vector<int> nodes{};  // the stations' nodes, filled by build()

  double L() const { return stations.back() - stations.front(); }
  double q() const { return section->rhoA() * kGravityTest; }  // weight per length (N/m)
  double EI() const { return section->material.E * kPi * std::pow(0.05, 4) / 64; }

  void build(Model& model) {
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    for (std::size_t s = 1; s < stations.size(); ++s)
      spec.segments.push_back({stations[s] - stations[s - 1], section, perSpan, 0, {}});
    std::vector<std::string> names;
    for (std::size_t s = 0; s < stations.size(); ++s) {
      const std::string index = std::to_string(s);
      names.push_back("s" + index);
      spec.points.push_back({names.back(), stations[s] - stations.front()});
    }
    buildLine(model, spec);
    for (const std::string& name : names) nodes.push_back(model.node(name));
  }
};

const Eigen::Vector3d kGravityDown(0, -kGravityTest, 0);

}  // namespace

TEST_SUITE("gravity bearing loads") {
  TEST_CASE("shaft and disk on two bearings: moment balance, any bearing stiffness") {
    // Stations 0, 0.2 (bearing A), 0.9 (disk, 30 kg), 1.3 (bearing B), 1.5 (end): overhangs
    // both sides. Statically determinate: B = (W_s (L/2 - xA) + W_d (xd - xA)) / (xB - xA),
    // A = W_s + W_d - B (moments about A). The consistent weight of the shaft is exact, so the
    // reactions match to round-off of the solve (measured up to 1e-11: K's condition number
    // amplifies it; asked 1e-9), rigid or elastic.
    StationShaft shaft{{0, 0.2, 0.9, 1.3, 1.5}};
    Model model;
    shaft.build(model);
    const double md = 30;
    model.add<PointInertia>(shaft.nodes[2], DofSet::lateral(), md, 0.3, 0.15,
                            Eigen::Vector3d::UnitX());
    model.add<Bearing>(shaft.nodes[1], BearingCoefficients::isotropic(2e8));
    model.add<Bearing>(shaft.nodes[3], BearingCoefficients{5e7, 1e7, -1e7, 8e7, 0, 0, 0, 0});
    const double Ws = shaft.q() * shaft.L(), Wd = md * kGravityTest;
    const double B = (Ws * (shaft.L() / 2 - 0.2) + Wd * (0.9 - 0.2)) / (1.3 - 0.2);
    const double A = Ws + Wd - B;
    for (BearingSupport support : {BearingSupport::rigid, BearingSupport::elastic}) {
      const GravityLoads g = solveGravityLoads(model, kGravityDown, support);
      REQUIRE(g.bearings.size() == 2);
      CHECK(relError(-g.weight.y(), Ws + Wd) < 1e-9);
      CHECK(relError(g.bearings[0].fy, A) < 1e-9);
      CHECK(relError(g.bearings[1].fy, B) < 1e-9);
      // No load across gravity: fz vanishes to round-off of the weight.
      CHECK(std::abs(g.bearings[0].fz) < 1e-9 * A);
      CHECK(std::abs(g.bearings[1].fz) < 1e-9 * B);
    }
  }

  TEST_CASE("uniform shaft on two end bearings: midspan sag 5 q L^4 / (384 E I)") {
    // Hermite elements with consistent loads are exact at the nodes for a uniform load
    // (measured 2e-15; asked 1e-10).
    StationShaft shaft{{0, 0.6, 1.2}};
    Model model;
    shaft.build(model);
    model.add<Bearing>(shaft.nodes.front(), BearingCoefficients::isotropic(1e8));
    model.add<Bearing>(shaft.nodes.back(), BearingCoefficients::isotropic(1e8));
    const GravityLoads g = solveGravityLoads(model, kGravityDown, BearingSupport::rigid);
    const double L = shaft.L();
    const int mid = g.largestSag();
    REQUIRE(mid >= 0);
    CHECK(g.x[mid] == doctest::Approx(0.6).epsilon(1e-12));
    CHECK(relError(-g.uy[mid], 5 * shaft.q() * std::pow(L, 4) / (384 * shaft.EI())) < 1e-10);
    // Elastic bearings add their own deflection, (q L / 2) / k, at every node.
    const GravityLoads e = solveGravityLoads(model, kGravityDown, BearingSupport::elastic);
    CHECK(relError(-e.uy[mid], 5 * shaft.q() * std::pow(L, 4) / (384 * shaft.EI()) +
                                   shaft.q() * L / 2 / 1e8) < 1e-10);
  }

  TEST_CASE("three bearings: two-span continuous beam, pinned and on springs") {
    // Two equal spans l on three supports under the uniform weight q: the pinned reactions are
    // 3/8 q l, 10/8 q l, 3/8 q l (three-moment equation). On three springs k: with R the
    // middle spring's force, the ends carry (2 q l - R) / 2 each and sink by that over k; the
    // middle sinks by that plus the simply supported beam's 5 q (2l)^4 / (384 E I) less
    // R (2l)^3 / (48 E I); R = k w_mid gives
    //   R = (q l + k 5 q (2l)^4 / (384 E I)) / (3/2 + k (2l)^3 / (48 E I)).
    // Exact at the nodes (asked 1e-10).
    const double l = 0.7;
    StationShaft shaft{{0, l, 2 * l}};
    Model model;
    shaft.build(model);
    const double k = 2e6;  // about 3 E I / l^3: the springs and the shaft share the compliance
    for (int node : shaft.nodes) model.add<Bearing>(node, BearingCoefficients::isotropic(k));
    const double q = shaft.q();
    const GravityLoads pinned = solveGravityLoads(model, kGravityDown, BearingSupport::rigid);
    CHECK(relError(pinned.bearings[0].fy, 3.0 / 8 * q * l) < 1e-10);
    CHECK(relError(pinned.bearings[1].fy, 10.0 / 8 * q * l) < 1e-10);
    CHECK(relError(pinned.bearings[2].fy, 3.0 / 8 * q * l) < 1e-10);
    const GravityLoads springs = solveGravityLoads(model, kGravityDown, BearingSupport::elastic);
    const double EI = shaft.EI();
    const double R = (q * l + k * 5 * q * std::pow(2 * l, 4) / (384 * EI)) /
                     (1.5 + k * std::pow(2 * l, 3) / (48 * EI));
    CHECK(relError(springs.bearings[1].fy, R) < 1e-10);
    CHECK(relError(springs.bearings[0].fy, (2 * q * l - R) / 2) < 1e-10);
    // The springs take load off the middle bearing: the test tells the two apart.
    CHECK(R < 0.9 * 10.0 / 8 * q * l);
  }

  TEST_CASE("a rotor on one pinned bearing is not held") {
    StationShaft shaft{{0, 1}};
    Model model;
    shaft.build(model);
    model.add<Bearing>(shaft.nodes.front(), BearingCoefficients::isotropic(1e8));
    CHECK_THROWS_WITH_AS(solveGravityLoads(model, kGravityDown, BearingSupport::rigid),
                         doctest::Contains("not held"), SolveError);
  }
}
