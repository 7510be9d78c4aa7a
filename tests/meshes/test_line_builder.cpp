// The line builder far from the origin: element lengths come from the segments (segment
// length / element count), not from differences of node coordinates, which at 9e4 m carry
// only about 1e-11 m (one unit in the last place of 9e4 is 1.5e-11 m) of a 0.06 m element.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "meshes/LineBuilder.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;

TEST_SUITE("line builder") {
  TEST_CASE("far from the origin every element keeps its segment's length to round-off") {
    Model model;
    const auto section = std::make_shared<const Section>(
        Section::rectangle("20x20", Material::fromEnu("steel", 210e9, 0.3, 7850), 0.02, 0.02));
    LineSpec spec;
    spec.start = {9e4, 0, 0};  // the far end of the planar bench model at 1.5e6 elements
    spec.segments = {{0.6, section, 10}, {0.3, section, 4}};
    spec.points = {{"load", 0.6 + 0.15}};  // inside the second segment: cuts it in two
    const Line line = buildLine(model, spec);
    REQUIRE(line.beams.size() == 14);  // 10, then the two 0.15 m halves, 2 elements each
    // Exact lengths 0.06 (first segment) and 0.075 (each half of the second, 2 elements):
    // one division each, so within two units in the last place (4.4e-16 relative); node
    // differences would be off by up to 2.4e-10 relative here.
    for (int e = 0; e < 10; ++e) CHECK(std::abs(line.beams[e]->length() / 0.06 - 1) < 4.5e-16);
    for (int e = 10; e < 14; ++e)
      CHECK(std::abs(line.beams[e]->length() / 0.075 - 1) < 4.5e-16);
    // The nodes still sit at their stations (coordinates to the last place of 9e4 m) and
    // the named point on a node.
    CHECK(std::abs(model.nodes()[line.nodes.back()].x() - (9e4 + 0.9)) < 3e-11);
    CHECK(std::abs(model.nodes()[model.node("load")].x() - (9e4 + 0.75)) < 3e-11);
  }
}
