// Eigenvalue runs on two threads at once (fem/solvers/ArpackTurn.hpp, BlasThreads.hpp): each
// must get what it gets alone, to the last bit. ARPACK keeps a run's state in Fortran SAVE
// variables, and the serial OpenBLAS shared its work buffers between calls: two Python threads
// solving rotor decks at once crashed the interpreter or returned other log decrements.
// Checked both ways: with the turn taken out both cases crashed (3 runs of 3, SIGSEGV and a
// corrupted heap); built against the serial OpenBLAS, the rotor case got other numbers in 5
// runs of 5.
#include <doctest/doctest.h>

#include <thread>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/modal/Modal.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorUnbalance.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Squared frequencies of a clamped planar line of `elements` beams: Lanczos (over 200 dofs).
std::vector<double> lineEigenvalues(int elements) {
  Model m;
  const Line line = uniformBeam(m, 1.5, steelCircle(0.04), elements, DofSet::planar(),
                                {BeamTheory::eulerBernoulli, MassModel::consistent});
  clamp(m, "root", line.nodes.front(), DofSet::planar());
  std::vector<double> values;
  for (const Mode& mode : solveModes(m, {8, 0}).modes) values.push_back(mode.eigenvalue);
  return values;
}

/// A shaft on cross-coupled bearings whose coefficients change with speed, with a disk.
Line shaftOnBearings(Model& m, int elements) {
  const Line line = uniformBeam(m, 2.0, steelCircle(0.08), elements, DofSet::lateral(),
                                {BeamTheory::timoshenko, MassModel::consistent, true});
  const BearingCoefficients slow{2e8, 1e7, -1e7, 3e8, 2e3, 0, 0, 3e3};
  const BearingCoefficients fast{3e8, 4e7, -4e7, 4e8, 1.5e3, 0, 0, 2e3};
  for (int at : {line.nodes.front(), line.nodes.back()})
    m.add<Bearing>(at, std::vector<double>{0, 1000}, std::vector<BearingCoefficients>{slow, fast});
  m.add<PointInertia>(line.nodes[elements / 2], DofSet::lateral(), 40, 0.8, 0.45);
  return line;
}

/// A Campbell diagram's eigenvalues (Arnoldi, ARPACK's non-symmetric driver, on UMFPACK's
/// factor of the unsymmetric K + sigma D + sigma^2 M) and an unbalance response's complex
/// amplitudes (UMFPACK's complex LU, which calls BLAS, at every speed).
std::vector<std::complex<double>> shaftResponse(int elements) {
  Model m;
  const Line line = shaftOnBearings(m, elements);
  std::vector<double> speeds;
  for (int s = 1; s <= 8; ++s) speeds.push_back(120.0 * s);
  std::vector<std::complex<double>> values;
  const CampbellResult campbell = solveCampbell(m, speeds, rotorOptions(4));
  for (const auto& modes : campbell.lines)
    for (const RotorMode& mode : modes) values.push_back(mode.eigenvalue);
  const int disk = line.nodes[elements / 2];
  const UnbalanceResult response = solveUnbalance(m, {{disk, 1e-4, 0}}, speeds, {disk});
  for (const Orbit& orbit : response.orbits[0]) {
    values.push_back(orbit.uy);
    values.push_back(orbit.uz);
  }
  return values;
}

/// Runs first() three times on a thread of its own while second() runs three times here.
template <class First, class Second>
void sideBySide(First&& first, Second&& second) {
  std::thread other([&] {
    for (int k = 0; k < 3; ++k) first();
  });
  for (int k = 0; k < 3; ++k) second();
  other.join();
}

}  // namespace

TEST_SUITE("arpack turn") {
  TEST_CASE("two Lanczos runs at once: each the lone run's eigenvalues, to the last bit") {
    const std::vector<double> short150 = lineEigenvalues(150), long170 = lineEigenvalues(170);
    REQUIRE(short150.size() == 8);
    int differing[2] = {0, 0};  // one counter a thread
    sideBySide([&] { differing[0] += lineEigenvalues(150) != short150; },
               [&] { differing[1] += lineEigenvalues(170) != long170; });
    CHECK(differing[0] == 0);
    CHECK(differing[1] == 0);
  }

  TEST_CASE("two rotor sweeps at once (Arnoldi, UMFPACK, BLAS): the lone sweeps' numbers") {
    const auto a = shaftResponse(60), b = shaftResponse(72);
    REQUIRE(a.size() == 4 * 8 + 2 * 8);
    int differing[2] = {0, 0};  // one counter a thread
    sideBySide([&] { differing[0] += shaftResponse(60) != a; },
               [&] { differing[1] += shaftResponse(72) != b; });
    CHECK(differing[0] == 0);
    CHECK(differing[1] == 0);
  }
}
