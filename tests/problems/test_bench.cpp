// The bench at small sizes: each kind works and its accuracy fields are small. Speed itself
// is measured by `make bench`, never here.
#include <doctest/doctest.h>

#include <gnu/libc-version.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "problems/bench/Bench.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

BenchOptions benchOptions(const std::string& kind, int elements, int modes) {
  BenchOptions o;
  o.kind = kind;
  o.elements = elements;
  o.modes = modes;
  o.repeat = 1;
  return o;
}

/// The fields the issue asks of every kind are in the JSON, with the report's values.
void checkCommonJson(const BenchReport& r) {
  const auto j = nlohmann::json::parse(benchJson(r));
  for (const char* key : {"assembly_s", "factor_s", "solve_s", "total_s"})
    CHECK(j.at("static").at(key).get<double>() >= 0);
  CHECK(j.at("modal").at("total_s").get<double>() > 0);
  CHECK(j.at("modal").at("frequencies_hz").size() == r.frequenciesHz.size());
  // The ratio the performance issue targets, from the same runs' medians.
  CHECK(j.at("modal").at("to_static").get<double>() ==
        doctest::Approx(r.median.modalTotal / r.median.staticTotal).epsilon(1e-12));
  CHECK(j.at("peak_rss_mb").get<double>() > 0);
  CHECK(j.at("dofs").get<int>() == r.dofs);
  CHECK(j.at("elements").get<int>() == r.elements);
  CHECK(j.at("rel_error_static").get<double>() == r.relErrorStatic);
  CHECK(j.at("factor_entries").get<double>() >= r.freeDofs);  // at least the diagonal
  CHECK(j.at("solver").get<std::string>() == r.solver);
}

}  // namespace

TEST_SUITE("bench") {
  TEST_CASE("planar standard model, 1000 elements: static exact, lowest mode by the dispersion") {
    const BenchReport r = runBench(benchOptions("planar", 1000, 4));
    CHECK(r.elements == 1000);
    CHECK(r.dofs == 3003);
    // Hermite elements with the consistent load vector give exact nodal deflections: the
    // midspan value of an interior span equals q s^4 / (384 E I) to round-off.
    CHECK(r.relErrorStatic < 1e-10);
    CHECK(r.figure("/midspan_w") < 0);
    // The discrete model at 10 elements per span lies above the continuous span frequency by
    // the Hermite elements' dispersion at k h = pi / 10, 6.7455e-6 (tests/Helpers.hpp; the
    // lowest mode is every span's pinned-pinned one). ARPACK's eigenvalue is converged to
    // ~1e-12 relative, 1e-7 of that gap.
    REQUIRE(!r.frequenciesHz.empty());
    CHECK(r.frequenciesHz[0] > r.figure("/modal/exact_lowest_hz"));
    const double gap = test::hermiteSimplySupportedFrequencyRatio(std::numbers::pi / 10) - 1;
    CHECK(test::relError(r.figure("/modal/rel_error_lowest"), gap) < 1e-5);
    checkCommonJson(r);
    const auto j = nlohmann::json::parse(benchJson(r));
    CHECK(j.at("midspan_w").get<double>() == r.figure("/midspan_w"));
  }

  TEST_CASE("grid3d, 4 x 4 bays: equilibrium, the square's symmetry, degenerate mode pair") {
    const BenchReport r = runBench(benchOptions("grid3d", 160, 4));
    const int bays = int(r.figure("/bays"));
    CHECK(bays == 4);
    CHECK(r.elements == gridElements(4));  // 8 n (n + 1) = 160
    // Free dofs counted by the DofMap against the closed count 42 n^2 + 6 (6 per node of the
    // 7 n^2 + 8 n + 1 nodes, less 3 at each of the 16 n boundary nodes).
    CHECK(r.freeDofs == 42 * 16 + 6);
    // Global equilibrium: the vertical reactions carry the 1000 N at each of the 7 n^2 + 8 n
    // + 1 = 145 nodes. Exact for any K (rigid-body translations are in its null space) up to
    // the solve's round-off (observed 8e-14), so 1e-10 is a wide margin.
    CHECK(r.figure("/total_load") == doctest::Approx(145 * 1000.0).epsilon(1e-15));
    CHECK(r.relErrorStatic < 1e-10);
    // D4 symmetry of the square holds node by node to round-off (observed 2e-14).
    CHECK(r.figure("/symmetry_error") < 1e-10);
    CHECK(r.figure("/centre_w") < 0);  // downwards, at the centre node (even bay count)
    // Modes 2 and 3 form a degenerate pair (the E representation of D4); ARPACK resolves
    // eigenvalues to its tolerance (1e-13 relative; observed split 1.5e-13).
    REQUIRE(r.frequenciesHz.size() == 4);
    CHECK(r.figure("/modal/pair_split") < 1e-9);
    CHECK(r.frequenciesHz[1] > r.frequenciesHz[0] * (1 + 1e-3));  // mode 1 is single
    checkCommonJson(r);
  }

  TEST_CASE("grid3d, one bay: every node pinned, so nothing moves and each pin carries 1000 N") {
    // Closed form: the 16 nodes all lie on the boundary, the loads act on pinned dofs only and
    // the free (rotation) dofs are unloaded, so u = 0 exactly and the reactions are the loads.
    const BenchReport r = runBench(benchOptions("grid3d", 16, 0));
    CHECK(r.figure("/bays") == 1);
    CHECK(r.elements == 16);
    CHECK(r.figure("/largest_w") == 0);
    CHECK(r.figure("/reaction_z") == 16 * 1000.0);
    CHECK(r.relErrorStatic == 0);
  }

  TEST_CASE("grid3d sized by --dofs: the grillage whose free dof count is nearest") {
    // n = 8 has 42 * 64 + 6 = 2694 free dofs, n = 9 has 3408: 3000 is nearer 2694.
    CHECK(closestSize(3000, gridFreeDofs) == 8);
    CHECK(closestSize(3100, gridFreeDofs) == 9);
    BenchOptions o = benchOptions("grid3d", 0, 0);
    o.dofs = 3000;
    const BenchReport r = runBench(o);
    CHECK(r.freeDofs == 2694);
    CHECK(r.frequenciesHz.empty());
    // planar: 3 dofs per node less 2 per span end; 1000 elements (100 spans) have 2801.
    BenchOptions p = benchOptions("planar", 0, 0);
    p.dofs = 2801;
    CHECK(runBench(p).elements == 1000);
  }

  TEST_CASE("rotor, 48 elements: weight on the bearings; at rest, the planar twin's modes") {
    const BenchReport r = runBench(benchOptions("rotor", 48, 6));
    CHECK(r.elements == 48);
    CHECK(r.freeDofs == 4 * 49);
    // Statics under self weight: the bearing forces balance the weight (equilibrium, exact up
    // to round-off; observed 5e-13 at this size).
    CHECK(r.relErrorStatic < 1e-10);
    CHECK(r.figure("/weight") > 0);
    // Campbell diagram: 50 speeds, one symbolic factorisation for the whole sweep.
    CHECK(r.figure("/campbell/speeds") == 50);
    CHECK(r.figure("/campbell/symbolic_analyses") <= 1);
    // At rest the planes decouple: the rotor's frequencies are the planar twin's, in pairs.
    // Two eigensolvers (Arnoldi on the state space, Lanczos on K, M) with tolerances 1e-13:
    // observed 8e-13; 1e-9 still catches a wrong mass or stiffness term (>= 1e-6).
    REQUIRE(r.frequenciesHz.size() == 6);
    CHECK(r.figure("/modal/rel_error_planar_twin") < 1e-9);
    CHECK(r.frequenciesHz[1] == doctest::Approx(r.frequenciesHz[0]).epsilon(1e-9));
    checkCommonJson(r);
  }

  TEST_CASE("the threads stated, and the answer the same to the last bit on one or three") {
    // 150 000 elements: three parts of 50 000 for each pass over the elements.
    const auto file = test::scratchDir("bench-threads") / "bench.json";
    const auto run = [&](const std::string& threads) {
      const auto r = test::runBeamrotor({"bench", "--kind", "planar", "--elements", "150000",
                                         "--modes", "2", "--repeat", "1", "--json",
                                         file.string()},
                                        BEAMROTOR_SOURCE_DIR, {"BEAMROTOR_THREADS=" + threads});
      REQUIRE(r.exitCode == 0);
      return nlohmann::json::parse(test::fileContents(file));
    };
    const nlohmann::json one = run("1"), three = run("3");
    CHECK(one.at("threads") == 1);
    CHECK(three.at("threads") == 3);
    CHECK(one.at("midspan_w").get<double>() == three.at("midspan_w").get<double>());
    CHECK(one.at("modal").at("frequencies_hz") == three.at("modal").at("frequencies_hz"));
    CHECK(three.at("rel_error_static").get<double>() < 1e-12);
  }

  TEST_CASE("a size the kind cannot build is an input error (exit 2)") {
    CHECK_THROWS_AS(runBench(benchOptions("planar", 5, 0)), std::invalid_argument);
    CHECK_THROWS_AS(runBench(benchOptions("tetrahedra", 1000, 0)), std::invalid_argument);
    using beamrotor::test::runBeamrotor;
    CHECK(runBeamrotor({"bench", "--kind", "planar", "--elements", "5"}).exitCode == 2);
    CHECK(runBeamrotor({"bench", "--kind", "grid3d", "--elements", "100", "--dofs", "100"})
              .exitCode == 2);
    CHECK(runBeamrotor({"bench", "--kind", "cube"}).exitCode == 2);
  }

  TEST_CASE("the command line's heap is on transparent huge pages, unless told to keep 4 KiB") {
    // Where the kernel gives huge pages on advice only (its usual setting) and glibc reads the
    // tunable (2.35 on), the command line starts itself again with glibc.malloc.hugetlb=1
    // (problems/cli/HugePages.hpp). Elsewhere there is nothing to see.
    std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    std::getline(setting, line);
    int major = 0, minor = 0;
    std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor);
    if (line.find("[madvise]") == std::string::npos || major * 100 + minor < 235) {
      MESSAGE("skipped: transparent huge pages are not given on advice here");
      return;
    }
    const auto file = test::scratchDir("huge-pages") / "bench.json";
    const auto hugePagesMb = [&](const std::string& tunables) {
      const auto r = test::runBeamrotor({"bench", "--kind", "planar", "--elements", "50000",
                                         "--modes", "0", "--repeat", "1", "--cold", "--json",
                                         file.string()},
                                        BEAMROTOR_SOURCE_DIR, {"GLIBC_TUNABLES=" + tunables});
      REQUIRE(r.exitCode == 0);
      return nlohmann::json::parse(test::fileContents(file)).at("huge_pages_mb").get<double>();
    };
    // 50 000 elements hold about 60 MB (1.2 kB an element at its peak, kept for reuse): most of
    // it in 2 MiB pages, against none when the user keeps glibc's default.
    CHECK(hugePagesMb("") >= 20);
    CHECK(hugePagesMb("glibc.malloc.hugetlb=0") == 0);
  }
}
