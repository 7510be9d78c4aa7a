// Mechanisms found on the element level and named in words: three hinges in a row, a free-free
// beam, a beam on one pin; and a clamped cantilever, however fine, is never one.
#include <doctest/doctest.h>

#include <string>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SupportCheck.hpp"
#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// The message of the UnsupportedStructure solving `model` throws ("" if none).
std::string mechanismMessage(const Model& model) {
  try {
    solveStatic(model);
  } catch (const UnsupportedStructure& e) {
    return e.what();
  }
  return "";
}

bool says(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_SUITE("mechanisms") {
  TEST_CASE("three hinges in a row: the two middle beams turn about the outer hinges") {
    // Clamped at x = 0 and 4 m, hinged at 1, 2 and 3 m: the beams 1-2 and 2-3 form a
    // three-hinged chain between the hinges at 1 and 3, one degree of freedom (the middle
    // hinge moves across the line, each beam turning about its outer hinge). Before: "the
    // stiffness matrix is singular to working precision", the mechanism not found.
    Model m;
    const Line line = uniformBeam(m, 4.0, steelCircle(0.05), 4);
    clamp(m, "left", line.nodes.front(), DofSet::planar());
    clamp(m, "right", line.nodes.back(), DofSet::planar());
    for (int k = 1; k <= 3; ++k) {
      const std::string index = std::to_string(k);
      m.nameNode("h" + index, line.nodes[k]);
      line.beams[k - 1]->release(1, Dof::rz);
      line.beams[k]->release(0, Dof::rz);
    }
    m.addLoad({line.nodes[2], Dof::uy, -100});
    const std::string msg = mechanismMessage(m);
    MESSAGE(msg);
    CHECK(says(msg, "not fully supported"));
    CHECK(says(msg, "(1 independent motion)"));
    CHECK(says(msg, "the beams from x = 1 m ('h1') to x = 2 m ('h2') turn about x = 1 m ('h1')"));
    CHECK(says(msg, "the beams from x = 2 m ('h2') to x = 3 m ('h3') turn about x = 3 m ('h3')"));
    CHECK(says(msg, "hinges at x = 1 m ('h1'), x = 2 m ('h2') and x = 3 m ('h3')"));
    CHECK_FALSE(says(msg, "x = 0 m"));  // the clamped outer beams rest
  }

  TEST_CASE("a free-free beam moves as a free body; a beam on one pin turns about it") {
    Model freeFree;
    uniformBeam(freeFree, 2.0, steelCircle(0.05), 4);
    const std::string free = mechanismMessage(freeFree);
    CHECK(says(free, "(3 independent motions)"));
    CHECK(
        says(free, "move as a free body (3 motions): translating along x and y, turning about z"));
    CHECK_FALSE(says(free, "hinge"));

    Model pinned;
    const Line line = uniformBeam(pinned, 2.0, steelCircle(0.05), 4);
    pinned.addSupport({"pin", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}}});
    const std::string turns = mechanismMessage(pinned);
    CHECK(says(turns, "(1 independent motion)"));
    CHECK(says(turns,
               "the beams from x = 0 m ('start') to x = 2 m ('end') turn about x = 0 m ('start')"));
  }

  TEST_CASE("a clamped cantilever is held on any mesh") {
    // cond(K) of a clamped cantilever grows as N^4 (6e18 at 5e4 elements, far past 1/eps),
    // but the element-level strain matrix B (K = B'B) only as N^2: its rank test sees a held
    // structure. Before: 50 000 elements were refused as "not fully supported; 100000 dof(s)
    // can move".
    for (int elements : {16, 50000}) {
      CAPTURE(elements);
      Model m;
      const Line line = uniformBeam(m, 1.2, steelCircle(0.05), elements);
      clamp(m, "root", line.nodes.front(), DofSet::planar());
      const DofMap dofs(m);
      const SparseMatrix K = SparseAssembler(m, dofs).assemble(MatrixKind::stiffness);
      CHECK(findMechanism(m, dofs, K).count == 0);
    }
  }
}
