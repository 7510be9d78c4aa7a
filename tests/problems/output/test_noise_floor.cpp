// The summary's round-off floor (problems/output/structure/NoiseFloor): each kind of value
// judged against the largest of its kind in the same solution, so that what is shown as 0 does
// not depend on the units, and a small value that is real stays.
#include <doctest/doctest.h>

#include "problems/output/structure/NoiseFloor.hpp"

using namespace beamrotor;

namespace {

/// Two nodes `length` apart along x; node 0 held (reactions in N, N m), node 1 displaced.
struct TwoNodes {
  Model model;
  StaticResult result;
};

TwoNodes twoNodes(double length, double forceScale, double roundOff) {
  TwoNodes t;
  t.model.addNode({0, 0, 0});
  t.model.addNode({length, 0, 0});
  t.result.displacement = NodalField::Zero(2, kDofKinds);
  t.result.displacement.row(1) << 1e-3 * length, 0, 1e-18 * length, 0, 1e-4, 0;
  t.result.roundOff = roundOff;
  const auto reaction = [&](Dof d, double value) {
    t.result.reactions.push_back({"A", 0, d, value});
  };
  reaction(Dof::ux, 1000 * forceScale);
  reaction(Dof::uy, 1e-6 * forceScale);   // 1e-9 of the largest force: real
  reaction(Dof::uz, 1e-12 * forceScale);  // 1e-15 of it: round-off
  reaction(Dof::rz, 0.5 * forceScale * length);
  reaction(Dof::rx, 1e-10 * forceScale * length);  // below 1e-12 of 1000 N x the 2 m model
  return t;
}

}  // namespace

TEST_SUITE("noise floor") {
  TEST_CASE("floors: the kind's largest value times the larger of the solve's error and 1e-12") {
    const TwoNodes t = twoNodes(2, 1, 1e-16);
    const NoiseFloor f = noiseFloorOf(t.model, t.result);
    // Translations: the largest, 2e-3 m. Rotations: the larger of 1e-4 rad and 2e-3 m over
    // the 2 m model. Forces: 1000 N. Moments: the larger of 1 N m and 1000 N x 2 m.
    CHECK(f.translation == doctest::Approx(kNegligibleShare * 2e-3).epsilon(1e-15));
    CHECK(f.rotation == doctest::Approx(kNegligibleShare * 1e-3).epsilon(1e-15));
    CHECK(f.force == doctest::Approx(kNegligibleShare * 1000).epsilon(1e-15));
    CHECK(f.moment == doctest::Approx(kNegligibleShare * 2000).epsilon(1e-15));
    CHECK(f.load(1e-6, false) == 1e-6);
    CHECK(f.load(1e-12, false) == 0);
    CHECK(f.load(-1e-10, true) == 0);
    CHECK(f.load(1, true) == 1);
    CHECK(f.motion(2e-18, Dof::uz) == 0);
    CHECK(f.motion(1e-4, Dof::ry) == 1e-4);
    // A solve that measured a larger error raises every floor with it.
    const NoiseFloor rough = noiseFloorOf(t.model, twoNodes(2, 1, 1e-8).result);
    CHECK(rough.force == doctest::Approx(1e-8 * 1000).epsilon(1e-15));
    CHECK(rough.load(1e-6, false) == 0);
  }

  TEST_CASE("the same values vanish in any units") {
    // The same structure in millimetres and kilonewtons: lengths x 1000, forces x 1e-3.
    const TwoNodes si = twoNodes(2, 1, 1e-16), scaled = twoNodes(2000, 1e-3, 1e-16);
    const NoiseFloor a = noiseFloorOf(si.model, si.result);
    const NoiseFloor b = noiseFloorOf(scaled.model, scaled.result);
    CHECK(b.translation == doctest::Approx(a.translation * 1000).epsilon(1e-14));
    CHECK(b.rotation == doctest::Approx(a.rotation).epsilon(1e-14));
    CHECK(b.force == doctest::Approx(a.force * 1e-3).epsilon(1e-14));
    CHECK(b.moment == doctest::Approx(a.moment * 1e-3 * 1000).epsilon(1e-14));
    for (std::size_t k = 0; k < si.result.reactions.size(); ++k) {
      const ReactionComponent& x = si.result.reactions[k];
      const ReactionComponent& y = scaled.result.reactions[k];
      CHECK((a.load(x.value, isRotation(x.dof)) == 0) == (b.load(y.value, isRotation(y.dof)) == 0));
    }
  }
}
