// Beams made one after another share their properties (Beam::Properties) while they are
// equal. A change to one beam (span load, hinge, preload) must reach that beam alone: each
// beam of a line is checked against a beam made on its own with the same data.
#include <doctest/doctest.h>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kLength = 2.4;
constexpr int kBeams = 4;

/// A beam made alone, with the data of each beam of the line (0.6 m, planar, along x).
Beam alone(int n1, int n2, std::shared_ptr<const Section> s) {
  return Beam(n1, n2, Eigen::Vector3d::UnitX(), kLength / kBeams, std::move(s), DofSet::planar());
}

}  // namespace

TEST_SUITE("beam shared properties") {
  TEST_CASE("a change to one beam leaves the beams it shared with as they were") {
    const auto sec = steelCircle(0.05);
    Model m;
    const Line line = uniformBeam(m, kLength, sec, kBeams);
    const std::vector<Beam*>& b = line.beams;
    const Eigen::Vector3d q(0, -300, 0);
    b[1]->setDistributedLoad(q);
    b[2]->release(1, Dof::rz);
    b[3]->setAxialPreload(-2e4);

    Beam plain = alone(line.nodes[0], line.nodes[1], sec);
    Beam loaded = alone(line.nodes[1], line.nodes[2], sec);
    loaded.setDistributedLoad(q);
    Beam hinged = alone(line.nodes[2], line.nodes[3], sec);
    hinged.release(1, Dof::rz);
    Beam preloaded = alone(line.nodes[3], line.nodes[4], sec);
    preloaded.setAxialPreload(-2e4);

    // Beam 0 kept everything: no load, all six dofs, the plain stiffness, no geometric term.
    CHECK(b[0]->load().size() == 0);
    CHECK(b[0]->dofs().size() == 6);
    CHECK(b[0]->stiffness() == plain.stiffness());
    const ElementVector still = ElementVector::Zero(6);
    CHECK(b[0]->geometricStiffness(still).isZero(0));
    // Each changed beam carries its own change, to the bit of a beam made with it alone.
    CHECK(b[1]->load() == loaded.load());
    CHECK(b[1]->load().norm() > 0);
    CHECK(b[1]->stiffness() == plain.stiffness());
    CHECK(b[2]->dofs().size() == 5);  // the released rz about global z is not coupled
    CHECK(b[2]->stiffness() == hinged.stiffness());
    CHECK(b[2]->load().size() == 0);
    CHECK(b[3]->geometricStiffness(still) == preloaded.geometricStiffness(still));
    CHECK_FALSE(b[3]->geometricStiffness(still).isZero(0));
    // Equal again (beam 1 loaded like beam 0 is not): the same matrices, as before the change.
    CHECK(b[0]->sameMatricesAs(plain));
    CHECK_FALSE(b[0]->sameMatricesAs(*b[1]));
  }

  TEST_CASE("an element's dofs: its own nodes with the kinds its properties keep") {
    const auto sec = steelCircle(0.05);
    Model m;
    const Line line = uniformBeam(m, kLength, sec, kBeams);
    line.beams[2]->release(0, Dof::rz);
    const ElementDofs d = line.beams[2]->dofs();
    // ux, uy of node 2 (its rz released about global z), then ux, uy, rz of node 3.
    const std::vector<NodeDof> expected{{line.nodes[2], Dof::ux},
                                        {line.nodes[2], Dof::uy},
                                        {line.nodes[3], Dof::ux},
                                        {line.nodes[3], Dof::uy},
                                        {line.nodes[3], Dof::rz}};
    CHECK((std::vector<NodeDof>(d.begin(), d.end()) == expected));
    for (std::size_t k = 0; k < expected.size(); ++k) CHECK((d[k] == expected[k]));
    // Its neighbours, which shared its properties before the release, keep all six.
    const ElementDofs before = line.beams[1]->dofs();
    CHECK(before.size() == 6);
    CHECK((before[5] == NodeDof{line.nodes[2], Dof::rz}));
  }
}
