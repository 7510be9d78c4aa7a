// What a frame of many members writes: one members table in place of a file per member above
// kMemberFilesUpTo members, its values against the closed form of a long continuous beam, and
// a frame chart whose data stays within its documented bounds.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "problems/output/PreparedRun.hpp"
#include "problems/output/structure/FrameCharts.hpp"
#include "problems/output/structure/MemberOutput.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

// Named, not anonymous: the test sources are compiled in unity batches.
namespace large_frame {

// A continuous beam of `spans` equal spans L under a uniform q, pinned at every joint, written
// as a planar frame of one member per span. Far from its ends it is the infinite continuous
// beam: M = -q L^2 / 12 over each support and q L^2 / 24 at midspan. The end spans' influence
// falls by 2 - sqrt(3) = 0.27 per span (three-moment equation), 1e-34 after 60 spans.
constexpr double kSpan = 4, kQ = 10e3;

std::string continuousBeam(int spans) {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: planar}\n"
    << "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
    << "sections: [{name: ipe, shape: general, A: 53.8e-4, I: 8356e-8, depth: 0.3}]\n"
    << "nodes:\n";
  for (int i = 0; i <= spans; ++i) d << "  - {name: J" << i << ", at: [" << kSpan * i << ", 0]}\n";
  d << "members:\n";
  for (int i = 0; i < spans; ++i)
    d << "  - {name: m" << i << ", from: J" << i << ", to: J" << i + 1
      << ", section: ipe, elements: 2}\n";
  d << "supports:\n  - {name: S0, at: J0, fix: pinned}\n";
  for (int i = 1; i <= spans; ++i) d << "  - {name: S" << i << ", at: J" << i << ", fix: [uy]}\n";
  d << "loads: [{type: distributed, qy: " << -kQ << "}]\n"
    << "analyses: [{type: static}]\n";
  return d.str();
}

}  // namespace large_frame

using namespace large_frame;

TEST_SUITE("output") {
  TEST_CASE("above 100 members one members table holds every member, exact along each") {
    constexpr int kSpans = 120;
    const Study s = test::solveDeckText(continuousBeam(kSpans), "long_beam.yaml");
    const RunResult& run = *s.run;
    const PreparedRun prepared = prepareRun(run);
    const PreparedAnalysis& p = prepared.analyses.front();
    REQUIRE(p.members.size() == 1);
    const CsvTable& table = p.members.front();
    CHECK(table.title() == "static_members.csv");
    CHECK(prepared.results.doc["analyses"][0]["members"]["m60"]["csv"] == "static_members.csv");
    // Every station of every element: 2 elements per member, 5 stations each.
    CHECK(table.rowCount() == std::size_t(kSpans) * 2 * 5);

    // The middle member's rows: hogging -q L^2 / 12 at its ends, sagging q L^2 / 24 at its
    // middle (its elements' shared end), s from its start. Euler-Bernoulli elements under a
    // uniform load recover the moment exactly; what remains is round-off of the solve.
    const double hog = -kQ * kSpan * kSpan / 12, sag = kQ * kSpan * kSpan / 24;
    const std::size_t member = table.column("member") - 1, sColumn = table.column("s") - 1,
                      mz = table.column("Mz") - 1;
    int seen = 0;
    for (std::size_t r = 0; r < table.rowCount(); ++r) {
      if (std::get<std::string>(table.cell(r, member)) != "m60") continue;
      const double at = std::get<double>(table.cell(r, sColumn));
      const double M = std::get<double>(table.cell(r, mz));
      const double x = at / kSpan;  // the moment of the infinite beam along a span
      const double exact = kQ * kSpan * kSpan * (x * (1 - x) / 2 - 1.0 / 12);
      CHECK(M == doctest::Approx(exact).epsilon(1e-9).scale(kQ * kSpan * kSpan));
      if (at == 0 || at == kSpan) CHECK(M == doctest::Approx(hog).epsilon(1e-9));
      if (std::abs(at - kSpan / 2) < 1e-12) CHECK(M == doctest::Approx(sag).epsilon(1e-9));
      ++seen;
    }
    CHECK(seen == 10);
  }

  TEST_CASE("up to 100 members each member keeps its own table") {
    const Study s = test::solveDeckText(continuousBeam(100), "hundred.yaml");
    const PreparedRun prepared = prepareRun(*s.run);
    const PreparedAnalysis& p = prepared.analyses.front();
    CHECK(p.members.size() == 100);
    CHECK(p.members.front().title() == "static_member_m0.csv");
    CHECK(prepared.results.doc["analyses"][0]["members"]["m7"]["csv"] == "static_member_m7.csv");
  }

  TEST_CASE("a large frame's chart draws within its bounds") {
    constexpr int kSpans = 3000;  // 30000 stations: every one is drawn; the diagrams are not
    const Study s = test::solveDeckText(continuousBeam(kSpans), "very_long_beam.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    const StaticResult& statics = *staticsOf(run.analyses.front());
    const std::vector<StaticStation> stations = sampleStatics({model, statics.displacement});
    const StationsByElement byElement(stations, model.elements().size());
    std::vector<std::array<ComponentRange, 6>> ranges;
    for (const auto& [name, elements] : model.members())
      ranges.push_back(memberForceRanges({model, statics.displacement}, elements));
    const FrameDrawing frame{&model, &byElement, &ranges,
                             largestDisplacement({model, statics.displacement}).value};
    const ChartScript chart = frameChart("long beam", "static_frame", frame, true);

    // Lines of each datablock: the outline's are its places; a diagram's, its stations.
    const auto blockLines = [&](const std::string& name) {
      const std::size_t start = chart.data.find(name + " << EOD\n");
      REQUIRE(start != std::string::npos);
      const std::size_t end = chart.data.find("EOD\n", start + name.size() + 8);
      const std::string block = chart.data.substr(start, end - start);
      return std::size_t(std::count(block.begin(), block.end(), '\n'));
    };
    CHECK(blockLines("$outline") <= kOutlinePoints + 3 * std::size_t(kSpans) + 1);
    // The diagrams: kDiagramMembers members of 10 stations each, with their blank separators.
    CHECK(blockLines("$Mz") <= kDiagramMembers * (10 + 2) + 1);
    CHECK(chart.body.find("(the 50 members of largest |M| among 3000)") != std::string::npos);
    // Labels: the largest moments only; no joint names among 3001.
    const auto labels = [&] {
      std::size_t n = 0;
      for (std::size_t at = chart.body.find("  set label"); at != std::string::npos;
           at = chart.body.find("  set label", at + 1))
        ++n;
      return n;
    }();
    CHECK(labels == kMomentLabels);
    CHECK(chart.body.find("'J1500'") == std::string::npos);
  }
}
