// The bench at its smallest size: it works and its accuracy fields are small. Speed itself is
// measured by `make bench`, never here.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "problems/bench/Bench.hpp"

using namespace beamrotor;

TEST_SUITE("bench") {
  TEST_CASE("planar standard model, 1000 elements: static exact, lowest mode 6.7e-6 high") {
    const BenchReport r = runBench({"planar", 1000, 4, 1});
    CHECK(r.elements == 1000);
    CHECK(r.dofs == 3003);
    // Hermite elements with the consistent load vector give exact nodal deflections: the
    // midspan value of an interior span equals q s^4 / (384 E I) to round-off.
    CHECK(r.relErrorStatic < 1e-10);
    // The discrete model at 10 elements per span lies 6.7e-6 above the continuous span
    // frequency (consistent mass converges from above at O(h^4)).
    REQUIRE(!r.frequenciesHz.empty());
    CHECK(r.frequenciesHz[0] > r.exactLowestHz);
    CHECK(r.relErrorLowestHz == doctest::Approx(6.7e-6).epsilon(0.05));
    const auto j = nlohmann::json::parse(benchJson(r));
    for (const char* key : {"assembly_s", "factor_s", "solve_s", "total_s"})
      CHECK(j.at("static").at(key).get<double>() >= 0);
    CHECK(j.at("rel_error_static").get<double>() == r.relErrorStatic);
  }
}
