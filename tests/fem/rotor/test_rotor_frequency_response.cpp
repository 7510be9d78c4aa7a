// Frequency response (receptance) against closed forms: an undamped two-mass chain, and
// Maxwell's reciprocity H_ij = H_ji for a non-rotating damped shaft.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/rotor/RotorFrequencyResponse.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// ground -k1- m1 -k2- m2 in y and z alike (a bearing for k1, springs for k2).
struct TwoMassChain {
  double m1 = 10, m2 = 4, k1 = 2e6, k2 = 1e6;
  int a = -1, b = -1;

  void build(Model& model) {
    a = model.addNode(Eigen::Vector3d::Zero());
    b = model.addNode(Eigen::Vector3d(1, 0, 0));
    const DofSet yz{Dof::uy, Dof::uz};
    model.add<PointInertia>(a, yz, m1);
    model.add<PointInertia>(b, yz, m2);
    model.add<Bearing>(a, BearingCoefficients::isotropic(k1));
    for (Dof d : {Dof::uy, Dof::uz}) model.add<Spring>(NodeDof{a, d}, NodeDof{b, d}, k2);
  }
  // H = Z^-1 with Z = [k1 + k2 - m1 w^2, -k2; -k2, k2 - m2 w^2].
  double det(double w) const {
    return (k1 + k2 - m1 * w * w) * (k2 - m2 * w * w) - k2 * k2;
  }
  double h11(double w) const { return (k2 - m2 * w * w) / det(w); }
  double h12(double w) const { return k2 / det(w); }
  double h22(double w) const { return (k1 + k2 - m1 * w * w) / det(w); }
};

}  // namespace

TEST_SUITE("rotor frequency response") {
  TEST_CASE("undamped two-mass chain: receptances against the inverse of its 2x2 stiffness") {
    TwoMassChain c;
    Model model;
    c.build(model);
    // Natural frequencies ~ 250 and 700 rad/s, the antiresonance of H11 at sqrt(k2 / m2) = 500:
    // frequencies between and around, none on one.
    const std::vector<double> w{0, 100, 300, 520, 650, 900, 2000};
    const auto r11 = solveFrequencyResponse(model, 0, {c.a, Dof::uy}, {c.a, Dof::uy}, w);
    const auto r21 = solveFrequencyResponse(model, 0, {c.a, Dof::uy}, {c.b, Dof::uy}, w);
    const auto r22 = solveFrequencyResponse(model, 0, {c.b, Dof::uz}, {c.b, Dof::uz}, w);
    const auto cross = solveFrequencyResponse(model, 0, {c.a, Dof::uy}, {c.b, Dof::uz}, w);
    for (std::size_t i = 0; i < w.size(); ++i) {
      CAPTURE(w[i]);
      // A direct 2x2 solve by LU: round-off of ~1e-15 times the conditioning (<1e3 away from
      // the resonances).
      CHECK(std::abs(r11.receptance[i] - c.h11(w[i])) < 1e-11 * std::abs(c.h11(w[i])));
      CHECK(std::abs(r21.receptance[i] - c.h12(w[i])) < 1e-11 * std::abs(c.h12(w[i])));
      CHECK(std::abs(r22.receptance[i] - c.h22(w[i])) < 1e-11 * std::abs(c.h22(w[i])));
      CHECK(std::abs(cross.receptance[i]) < 1e-20);  // y and z uncoupled at rest
      // Undamped: real receptance, its sign flipping across each resonance (phase 0 or 180).
      CHECK(std::abs(r11.receptance[i].imag()) <= 1e-14 * std::abs(r11.receptance[i]));
    }
  }

  TEST_CASE("reciprocity of a non-rotating damped shaft: H_ij = H_ji") {
    Model model;
    auto sec = std::make_shared<Section>(
        Section::circle("shaft", Material::fromEnu("steel", 2.1e11, 0.3, 7850), 0.05));
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    spec.segments.push_back({1.0, sec, 10, 0, {BeamTheory::timoshenko, MassModel::consistent, true}});
    spec.points = {{"A", 0.1}, {"mid", 0.45}, {"B", 0.9}};
    buildLine(model, spec);
    model.add<Bearing>(model.node("A"), BearingCoefficients{2e7, 0, 0, 3e7, 400, 0, 0, 600});
    model.add<Bearing>(model.node("B"), BearingCoefficients{2.5e7, 0, 0, 2e7, 500, 0, 0, 300});
    const int a = model.node("A"), m = model.node("mid");
    const std::vector<double> w{50, 400, 1200, 3000};
    const auto ij = solveFrequencyResponse(model, 0, {a, Dof::uy}, {m, Dof::rz}, w, {0, 1e-5});
    const auto ji = solveFrequencyResponse(model, 0, {m, Dof::rz}, {a, Dof::uy}, w, {0, 1e-5});
    for (std::size_t i = 0; i < w.size(); ++i) {
      CAPTURE(w[i]);
      // Symmetric K, C, M: the dynamic stiffness is complex symmetric, so is its inverse;
      // the two solves differ by round-off only.
      CHECK(std::abs(ij.receptance[i] - ji.receptance[i]) < 1e-10 * std::abs(ij.receptance[i]));
      CHECK(std::abs(ij.receptance[i].imag()) > 0);  // damped: not trivially real
    }
  }
}
