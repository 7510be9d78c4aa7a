// Modes about a loaded state: a pinned beam under an axial force has, mode by mode,
// f_n^2 = f0_n^2 (1 - P / Pcr_n), Pcr_n = n^2 pi^2 EI / L^2 (compression P > 0 lowers every
// frequency, tension raises it), from EI w'''' + P w'' + rho A w_tt = 0 with w = sin(n pi x / L).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "fem/solvers/Errors.hpp"
#include "fem/stability/Prestressed.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A pinned steel beam, 2 m, circle 50 mm, 32 elements, end load -P along x (P > 0 presses).
Model pinnedBeamUnderAxialLoad(double P) {
  Model m;
  const Line line = uniformBeam(m, 2.0, steelCircle(0.05), 32);
  m.addSupport({"start", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}}});
  m.addSupport({"end", line.nodes.back(), {{Dof::uy, 0}}});
  m.addLoad({line.nodes.back(), Dof::ux, -P});
  return m;
}

}  // namespace

TEST_SUITE("prestressed modes") {
  TEST_CASE("a pinned beam's bending frequencies follow f^2 = f0^2 (1 - P / Pcr_n)") {
    // Exact continuum values for modes 1..3 at P = +-0.6 Pcr_1. Measured FE errors with 32
    // Hermite elements and consistent mass: 1.6e-7, 1.2e-6, 5.6e-6 for modes 1, 2, 3 in
    // compression (4e-8, 9e-7, 4.9e-6 in tension), growing as (n h)^4; tolerance 1e-5.
    auto sec = steelCircle(0.05);
    const double L = 2.0, EI = sec->EIz(), rhoA = sec->rhoA();
    const double Pe = kPi * kPi * EI / (L * L);
    ModalOptions options;
    options.modes = 3;
    for (double P : {0.6 * Pe, -0.6 * Pe}) {
      const ModalResult r = solvePrestressedModes(pinnedBeamUnderAxialLoad(P), options);
      REQUIRE(r.modes.size() == 3);
      for (int n = 1; n <= 3; ++n) {
        const double k = n * kPi / L;
        const double f0 = k * k * std::sqrt(EI / rhoA) / (2 * kPi);
        const double exact = f0 * std::sqrt(1 - P / (n * n * Pe));
        MESSAGE("P = " << P / Pe << " Pe, mode " << n << ": error "
                       << relError(r.modes[n - 1].frequencyHz, exact));
        CHECK(relError(r.modes[n - 1].frequencyHz, exact) < 1e-5);
      }
    }
  }

  TEST_CASE("past the critical load the modes are refused, naming the buckling factor") {
    auto sec = steelCircle(0.05);
    const double Pe = kPi * kPi * sec->EIz() / 4.0;
    try {
      solvePrestressedModes(pinnedBeamUnderAxialLoad(1.25 * Pe));
      FAIL("no error past the critical load");
    } catch (const SolveError& e) {
      const std::string msg = e.what();
      CHECK(msg.find("prestressed modal analysis") != std::string::npos);
      CHECK(msg.find("buckling factor of its first-order state is 0.8") != std::string::npos);
    }
  }
}
