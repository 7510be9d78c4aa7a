// A moving load on a structure that carries the deck's own loads: each envelope is the deck
// loads' static value plus the train's extreme, and at the governing position a direct static
// solve of the deck's loads plus the wheels (as point loads at their places, the members cut
// there: no influence line involved) gives the reported extreme. Both are exact (consistent
// nodal loads and the clamped share against nodes at the loads), so the tolerance is
// round-off: 1e-9 relative to the quantity's scale. The envelope file <stem>_envelope.vtu is
// read back with VTK's own reader and compared with the run's numbers and results.json.
#include <doctest/doctest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/output/Output.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TwoSpanFrame.hpp"

using namespace beamrotor;

namespace moving_dead_load {

// Two spans of 6 m on pins A, B, C, 5 elements each (no node at mid-span of span 2, so
// governing wheels fall inside elements), under a dead load (a distributed load on both spans
// and a point load on span 2); a two-wheel trolley of 40 kN and 25 kN, 1.7 m apart, crosses
// from A to C.
const std::string kDeadDeck = test::twoSpanFrame(5) + R"(loads:
  - {type: distributed, member: span1, qy: -8 kN/m}
  - {type: distributed, member: span2, qy: -5 kN/m}
  - {type: point, at: {member: span2, at: 0.3}, fy: -12 kN}
)";

const std::string kDeadAnalysis = R"(analyses:
  - type: moving-load
    name: trolley
    path: [span1, span2]
    wheels: [{force: 40 kN}, {force: 25 kN, offset: 1.7 m}]
    quantities: [reaction B uy, resultant Mz at B, resultant Mz at m1, resultant Vy at m1,
                 displacement m1 uy]
    field_envelopes: true
)";

constexpr double kDeadSpan = 6;

/// Relative round-off bound of the exact methods against each other (each quantity's values
/// are of order 1e5 N, 1e5 N m, 1e-3 m; both sides lose a few ulps per cubic and solve).
constexpr double kDeadRoundOff = 1e-9;

/// The static deck with the wheels of `run` standing with the first at `lead`: each wheel on
/// the path as a point load at its place (the member cut there).
std::string deadStaticDeckAt(double lead, const std::string& quantity, double reference) {
  std::string loads;
  const double forces[] = {40e3, 25e3}, offsets[] = {0, 1.7};
  for (int w = 0; w < 2; ++w) {
    const double s = lead - offsets[w];
    if (s < 0 || s > 2 * kDeadSpan) continue;
    const bool first = s < kDeadSpan;
    const double at = first ? s / kDeadSpan : (s - kDeadSpan) / kDeadSpan;
    char line[200];
    std::snprintf(line, sizeof line, "  - {type: point, at: {member: %s, at: %.17g}, fy: %.17g}\n",
                  first ? "span1" : "span2", at, -forces[w]);
    loads += line;
  }
  char check[300];
  std::snprintf(check, sizeof check,
                "checks:\n  - {name: direct, quantity: %s, reference: %.17g, tolerance: %g}\n",
                quantity.c_str(), reference, kDeadRoundOff);
  return kDeadDeck + loads + "analyses: [{type: static}]\n" + check;
}

const MovingLoadOutcome& deadMovingOf(const Study& study) {
  return std::get<MovingLoadOutcome>(study.run->analyses.front().result);
}

}  // namespace moving_dead_load

TEST_SUITE("moving load with the deck's loads") {
  TEST_CASE("each extreme is the deck loads' value plus the train's, and a direct solve agrees") {
    using namespace moving_dead_load;
    const Study withDeck = test::solveDeckText(kDeadDeck + kDeadAnalysis, "dead.yaml");
    std::string alone = kDeadAnalysis;
    alone.replace(alone.find("    path:"), 0, "    deck_loads: false\n");
    const Study trainAlone = test::solveDeckText(kDeadDeck + alone, "alone.yaml");
    const MovingLoadOutcome& m = deadMovingOf(withDeck);
    const MovingLoadOutcome& t = deadMovingOf(trainAlone);
    CHECK(m.deckLoads);
    CHECK_FALSE(t.deckLoads);
    REQUIRE(m.quantities.size() == 5);
    for (std::size_t i = 0; i < m.quantities.size(); ++i) {
      const MovingQuantity& q = m.quantities[i];
      CAPTURE(q.text);
      const double scale = std::max(std::abs(q.envelope.max.value), std::abs(q.envelope.min.value));
      // The deck loads alone, by a static analysis of the same deck.
      const Study still = test::solveDeckText(
          kDeadDeck + "analyses: [{type: static}]\nchecks:\n  - {name: still, quantity: " + q.text +
              ", reference: 1, tolerance: 1}\n",
          "still.yaml");
      const double deckValue = still.run->checks.front().computed;
      CHECK(std::abs(q.deckValue - deckValue) <= kDeadRoundOff * scale);
      CHECK(t.quantities[i].deckValue == 0);
      // The train alone's extremes, shifted by the deck's value, at the same positions.
      CHECK(std::abs(q.envelope.max.value - (t.quantities[i].envelope.max.value + deckValue)) <=
            kDeadRoundOff * scale);
      CHECK(std::abs(q.envelope.min.value - (t.quantities[i].envelope.min.value + deckValue)) <=
            kDeadRoundOff * scale);
      CHECK(q.envelope.max.lead == t.quantities[i].envelope.max.lead);
      // A direct static solve with the wheels where the train's extreme puts them.
      for (const TrainExtreme& e : {q.envelope.max, q.envelope.min}) {
        // A shear force read where a wheel stands jumps: its extreme is one side's limit,
        // which a static solve (the wheel on the node) does not give; skip those places.
        if (q.text.find("Vy") != std::string::npos &&
            (std::abs(e.lead - kDeadSpan / 2) < 1e-9 || std::abs(e.lead - 1.7 - kDeadSpan / 2) < 1e-9))
          continue;
        const Study direct =
            test::solveDeckText(deadStaticDeckAt(e.lead, q.text, e.value), "direct.yaml");
        const Check& c = direct.run->checks.front();
        MESSAGE(q.text << " at lead " << e.lead << ": moving " << e.value << ", direct "
                       << c.computed << " (relative " << c.relError() << ")");
        CHECK(std::abs(c.computed - e.value) <= kDeadRoundOff * scale);
      }
    }
    // The field envelopes hold the same numbers at the quantity's place: the node's
    // displacement and the resultant at the start of the element that starts at B.
    const Model& model = *withDeck.run->model;
    const int m1 = model.node("m1");
    const MovingQuantity& w = m.quantity("displacement m1 uy");
    CHECK(m.fields.nodes.at(std::size_t(m1))[1].min.value == doctest::Approx(w.envelope.min.value).epsilon(kDeadRoundOff));
    CHECK(m.fields.nodes.at(std::size_t(m1))[1].max.value == doctest::Approx(w.envelope.max.value).epsilon(kDeadRoundOff));
  }

  TEST_CASE("the envelope VTK file holds the run's envelopes and governing shapes") {
    using namespace moving_dead_load;
    const Study study = test::solveDeckText(kDeadDeck + kDeadAnalysis, "dead.yaml");
    const RunResult& run = *study.run;
    const MovingLoadOutcome& m = deadMovingOf(study);
    const std::filesystem::path dir = test::scratchDir("moving_vtk") / "out";
    OutputChoices choices;
    choices.charts = ChartFormat::none;
    writeRunOutputs(run, dir, choices);
    std::ifstream jsonFile(dir / "results.json");
    const nlohmann::json doc = nlohmann::json::parse(jsonFile);
    const nlohmann::json& a = doc.at("analyses").at(0);
    CHECK(a.at("deck_loads") == true);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / a.at("files").at("envelope_vtu").get<std::string>()).string().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    const Model& model = *run.model;
    REQUIRE(grid->GetNumberOfPoints() == model.nodeCount());
    vtkDataArray* high = grid->GetPointData()->GetArray("displacement_max [m]");
    vtkDataArray* low = grid->GetPointData()->GetArray("displacement_min [m]");
    REQUIRE(high);
    REQUIRE(low);
    // At m1, against the quantity's envelope in results.json (the written doubles, exactly).
    const int m1 = model.node("m1");
    for (const nlohmann::json& q : a.at("quantities"))
      if (q.at("quantity") == "displacement m1 uy") {
        CHECK(low->GetComponent(m1, 1) == doctest::Approx(q.at("min").at("value").get<double>()).epsilon(kDeadRoundOff));
        CHECK(high->GetComponent(m1, 1) == doctest::Approx(q.at("max").at("value").get<double>()).epsilon(kDeadRoundOff));
        // The shape where it is smallest: m1's own displacement there is that smallest value.
        vtkDataArray* shape =
            grid->GetPointData()->GetArray("displacement at min of displacement m1 uy [m]");
        REQUIRE(shape);
        CHECK(shape->GetComponent(m1, 1) == doctest::Approx(q.at("min").at("value").get<double>()).epsilon(kDeadRoundOff));
        vtkDataArray* lead = grid->GetFieldData()->GetArray("first wheel at min of displacement m1 uy [m]");
        REQUIRE(lead);
        CHECK(lead->GetTuple1(0) == q.at("min").at("first_wheel_at").get<double>());
      }
    // Every node's envelope: each component's band holds the deck loads' own displacement.
    for (vtkIdType n = 0; n < grid->GetNumberOfPoints(); ++n)
      for (int k = 0; k < 3; ++k) {
        CHECK(high->GetComponent(n, k) == m.fields.nodes[std::size_t(n)][std::size_t(k)].max.value);
        CHECK(low->GetComponent(n, k) <= high->GetComponent(n, k));
      }
    // Cell data: the hogging moment over the elements meeting B is results.json's moment at B.
    vtkDataArray* mzMin = grid->GetCellData()->GetArray("Mz_min [N m]");
    vtkDataArray* element = grid->GetCellData()->GetArray("element");
    REQUIRE(mzMin);
    REQUIRE(element);
    double mzB = 0;
    for (const nlohmann::json& q : a.at("quantities"))
      if (q.at("quantity") == "resultant Mz at B") mzB = q.at("min").at("value").get<double>();
    const int b = model.node("B");
    double leastAtB = 0;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
      const auto* line = asLine(model.elements()[std::size_t(element->GetTuple1(c))]);
      REQUIRE(line);
      const auto& ends = m.fields.elementEnds[std::size_t(element->GetTuple1(c))];
      CHECK(mzMin->GetTuple1(c) == std::min(ends[0][5].min.value, ends[1][5].min.value));
      if (line->endNodes()[0] == b) leastAtB = ends[0][5].min.value;
    }
    CHECK(leastAtB == doctest::Approx(mzB).epsilon(kDeadRoundOff));
    std::filesystem::remove_all(dir.parent_path());
  }

  TEST_CASE("without field_envelopes the VTK file holds the governing shapes alone") {
    using namespace moving_dead_load;
    std::string deck = kDeadDeck + kDeadAnalysis;
    deck.erase(deck.find("    field_envelopes: true\n"), std::string("    field_envelopes: true\n").size());
    const Study study = test::solveDeckText(deck, "shapes_only.yaml");
    const MovingLoadOutcome& m = deadMovingOf(study);
    CHECK(m.fields.nodes.empty());
    const std::filesystem::path dir = test::scratchDir("moving_vtk_shapes") / "out";
    OutputChoices choices;
    choices.charts = ChartFormat::none;
    writeRunOutputs(*study.run, dir, choices);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "trolley_envelope.vtu").string().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    CHECK(grid->GetPointData()->GetArray("displacement_max [m]") == nullptr);
    vtkDataArray* shape = grid->GetPointData()->GetArray("displacement at max of displacement m1 uy [m]");
    REQUIRE(shape != nullptr);
    // The governing shape at m1 is the envelope's value there (the deck's loads included).
    const int m1 = study.run->model->node("m1");
    CHECK(shape->GetComponent(m1, 1) ==
          doctest::Approx(m.quantity("displacement m1 uy").envelope.max.value).epsilon(kDeadRoundOff));
    std::filesystem::remove_all(dir.parent_path());
  }
}
