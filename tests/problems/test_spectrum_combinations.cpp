// The vertical spectrum beside the horizontals in one response-spectrum analysis (EN 1998-1
// 4.3.3.5.2): each direction alone equals an analysis excited along that direction only (the
// horizontal spectrum along x and z, the vertical one along y), and each combination of the
// directions, E_x + 0.3 E_y + 0.3 E_z and its permutations (or their SRSS), equals the same
// sums of those single-direction peaks taken by hand, for every reaction, displacement and
// member resultant; the combined peak is the largest combination, and the files say which
// governs. Same model, same modes: the tolerance is round-off (1e-12 of each quantity's
// scale).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/output/Output.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace spectrum_combinations {

// A table frame: four steel columns 3 m high on clamps, tied at the top by four beams of a
// 4 m x 5 m rectangle, 2 elements per member, with a 2 t machine at one top corner (so the
// modes couple the directions).
const std::string kTableFrame = R"(model: {dimension: 3d}
materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]
sections: [{name: s, shape: general, A: 53.8 cm^2, Iy: 8356 cm^4, Iz: 3000 cm^4, J: 50 cm^4,
            depth: 300 mm, width: 150 mm}]
nodes:
  - {name: A0, at: [0, 0, 0]}
  - {name: A1, at: [4, 0, 0]}
  - {name: A2, at: [4, 0, 5]}
  - {name: A3, at: [0, 0, 5]}
  - {name: B0, at: [0, 3, 0]}
  - {name: B1, at: [4, 3, 0]}
  - {name: B2, at: [4, 3, 5]}
  - {name: B3, at: [0, 3, 5]}
members:
  - {name: c0, from: A0, to: B0, section: s, elements: 2}
  - {name: c1, from: A1, to: B1, section: s, elements: 2}
  - {name: c2, from: A2, to: B2, section: s, elements: 2}
  - {name: c3, from: A3, to: B3, section: s, elements: 2}
  - {name: b01, from: B0, to: B1, section: s, elements: 2}
  - {name: b12, from: B1, to: B2, section: s, elements: 2}
  - {name: b23, from: B2, to: B3, section: s, elements: 2}
  - {name: b30, from: B3, to: B0, section: s, elements: 2}
supports:
  - {name: A0, at: A0, fix: clamped}
  - {name: A1, at: A1, fix: clamped}
  - {name: A2, at: A2, fix: clamped}
  - {name: A3, at: A3, fix: clamped}
masses: [{name: machine, at: B2, m: 2000 kg}]
)";

const std::string kHorizontalSpectrum = "{code: EN1998-1, type: 1, ground: C, ag: 2.5 m/s^2}";
const std::string kVerticalSpectrum = "{code: EN1998-1, type: 1, component: vertical, ag: 2.5 m/s^2}";

std::string combinationAnalyses(const std::string& directional) {
  return "analyses:\n"
         "  - {type: response-spectrum, name: all, modes: 24, spectrum: " + kHorizontalSpectrum +
         ", vertical_spectrum: " + kVerticalSpectrum + ", directions: [x, y, z], directional: " +
         directional + "}\n"
         "  - {type: response-spectrum, name: only_x, modes: 24, spectrum: " + kHorizontalSpectrum +
         ", directions: [x]}\n"
         "  - {type: response-spectrum, name: only_y, modes: 24, spectrum: " + kVerticalSpectrum +
         ", directions: [y]}\n"
         "  - {type: response-spectrum, name: only_z, modes: 24, spectrum: " + kHorizontalSpectrum +
         ", directions: [z]}\n";
}

const ResponseSpectrumResult& spectrumNamed(const Study& study, const std::string& name) {
  for (const AnalysisOutcome& a : study.run->analyses)
    if (a.name == name) return std::get<ResponseSpectrumResult>(a.result);
  throw std::invalid_argument("no analysis " + name);
}

/// Every quantity of a peak response as one list: displacements, reactions, section forces.
std::vector<double> peakValues(const PeakResponse& p) {
  std::vector<double> v(p.displacement.data(), p.displacement.data() + p.displacement.size());
  for (const ReactionComponent& c : p.reactions) v.push_back(c.value);
  for (const BeamStation& s : p.stations)
    for (double f : {s.forces.N, s.forces.Vy, s.forces.Vz, s.forces.T, s.forces.My, s.forces.Mz})
      v.push_back(f);
  for (double b : p.baseForce) v.push_back(b);
  return v;
}

/// Round-off of the same modes combined in two orders.
constexpr double kCombinationRoundOff = 1e-12;

/// The largest |a - b| over the quantities, relative to the largest |b| of the same kind
/// (displacements, reactions, forces: one scale each is enough for this check's purpose).
double worstPeakDifference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double scale = 0, worst = 0;
  for (double x : b) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst / scale;
}

}  // namespace spectrum_combinations

TEST_SUITE("response spectrum: the vertical with the horizontals") {
  TEST_CASE("each 100/30 combination is E_x + 0.3 E_y + 0.3 E_z of the single-direction runs") {
    using namespace spectrum_combinations;
    const Study study = test::solveDeckText(kTableFrame + combinationAnalyses("100/30"), "table.yaml");
    const ResponseSpectrumResult& all = spectrumNamed(study, "all");
    REQUIRE(all.verticalSpectrum);
    REQUIRE(all.directions == std::vector<int>{0, 1, 2});
    // Along y the vertical spectrum: mode j reads (3.8)-(3.11), not the horizontal plateau.
    const ResponseSpectrumResult& onlyY = spectrumNamed(study, "only_y");
    for (std::size_t j = 0; j < all.modal.modes.size(); ++j)
      CHECK(all.saOf(j, 1) == onlyY.spectralAcceleration[j]);
    // Each direction alone against its own analysis.
    const std::vector<double> singles[3] = {peakValues(spectrumNamed(study, "only_x").combined),
                                            peakValues(onlyY.combined),
                                            peakValues(spectrumNamed(study, "only_z").combined)};
    for (int d = 0; d < 3; ++d) {
      const double error = worstPeakDifference(peakValues(all.perDirection[std::size_t(d)]), singles[d]);
      MESSAGE("direction " << std::string(directionName(d)) << " alone: " << error);
      CHECK(error <= kCombinationRoundOff);
    }
    // Each combination by hand.
    REQUIRE(all.combinations.size() == 3);
    const char* names[] = {"x + 0.3 y + 0.3 z", "y + 0.3 x + 0.3 z", "z + 0.3 x + 0.3 y"};
    std::vector<double> largest(singles[0].size(), 0.0);
    for (int lead = 0; lead < 3; ++lead) {
      const DirectionalCombination& c = all.combinations[std::size_t(lead)];
      CHECK(c.name == names[lead]);
      std::vector<double> hand(singles[0].size());
      for (std::size_t i = 0; i < hand.size(); ++i) {
        for (int d = 0; d < 3; ++d) hand[i] += (d == lead ? 1.0 : 0.3) * singles[d][i];
        largest[i] = std::max(largest[i], hand[i]);
      }
      const double error = worstPeakDifference(peakValues(c.peak), hand);
      MESSAGE(c.name << " against the hand sum: " << error);
      CHECK(error <= kCombinationRoundOff);
    }
    CHECK(worstPeakDifference(peakValues(all.combined), largest) <= kCombinationRoundOff);
    // The vertical governs some quantity (the beams' vertical bending) and a horizontal
    // another (the columns' base shear): the combinations are not one another's multiples.
    std::vector<int> governs(3, 0);
    for (std::size_t i = 0; i < largest.size(); ++i)
      for (int lead = 0; lead < 3; ++lead)
        if (largest[i] > 0 && peakValues(all.combinations[std::size_t(lead)].peak)[i] == largest[i]) {
          ++governs[std::size_t(lead)];
          break;
        }
    CHECK(governs[1] > 0);
    CHECK(governs[0] + governs[2] > 0);
  }

  TEST_CASE("SRSS of the three directions, by hand") {
    using namespace spectrum_combinations;
    const Study study = test::solveDeckText(kTableFrame + combinationAnalyses("srss"), "table.yaml");
    const ResponseSpectrumResult& all = spectrumNamed(study, "all");
    REQUIRE(all.combinations.size() == 1);
    CHECK(all.combinations.front().name == "SRSS");
    const std::vector<double> x = peakValues(spectrumNamed(study, "only_x").combined),
                              y = peakValues(spectrumNamed(study, "only_y").combined),
                              z = peakValues(spectrumNamed(study, "only_z").combined);
    std::vector<double> hand(x.size());
    for (std::size_t i = 0; i < hand.size(); ++i)
      hand[i] = std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
    CHECK(worstPeakDifference(peakValues(all.combined), hand) <= kCombinationRoundOff);
    CHECK(worstPeakDifference(peakValues(all.combinations.front().peak), hand) <= kCombinationRoundOff);
  }

  TEST_CASE("the combinations reach results.json and the combinations table") {
    using namespace spectrum_combinations;
    const Study study = test::solveDeckText(kTableFrame + combinationAnalyses("100/30"), "table.yaml");
    const ResponseSpectrumResult& all = spectrumNamed(study, "all");
    const std::filesystem::path dir = test::scratchDir("spectrum_combinations") / "out";
    OutputChoices choices;
    choices.charts = ChartFormat::none;
    writeRunOutputs(*study.run, dir, choices);
    std::ifstream jsonFile(dir / "results.json");
    const nlohmann::json doc = nlohmann::json::parse(jsonFile);
    const nlohmann::json& a = doc.at("analyses").at(0);
    REQUIRE(a.at("combinations").size() == 3);
    CHECK(a.at("vertical_spectrum").get<std::string>().find("vertical") != std::string::npos);
    for (std::size_t c = 0; c < 3; ++c) {
      const nlohmann::json& entry = a.at("combinations").at(c);
      CHECK(entry.at("name") == all.combinations[c].name);
      for (std::size_t i = 0; i < all.combinations[c].peak.reactions.size(); ++i)
        CHECK(entry.at("reactions").at(i).at("value").get<double>() ==
              all.combinations[c].peak.reactions[i].value);
    }
    // Each combined reaction names the combination that gives it, whose value it is.
    for (const nlohmann::json& reaction : a.at("combined").at("reactions")) {
      const std::string governing = reaction.at("combination");
      for (const nlohmann::json& entry : a.at("combinations"))
        if (entry.at("name") == governing)
          for (const nlohmann::json& own : entry.at("reactions"))
            if (own.at("support") == reaction.at("support") && own.at("dof") == reaction.at("dof"))
              CHECK(own.at("value").get<double>() == reaction.at("value").get<double>());
    }
    const auto rows = test::csvCells(dir / "all_spectrum_combinations.csv");
    REQUIRE(rows.size() > 1);
    const std::size_t quantity = test::csvColumn(rows[0], "quantity"),
                      governs = test::csvColumn(rows[0], "governs"),
                      value = test::csvColumn(rows[0], "value");
    // Per quantity one governing row of three, holding the largest value.
    int governingRows = 0;
    for (std::size_t r = 1; r + 2 < rows.size(); r += 3) {
      CHECK(rows[r][quantity] == rows[r + 2][quantity]);
      double best = 0;
      for (std::size_t k = 0; k < 3; ++k) best = std::max(best, std::stod(rows[r + k][value]));
      int marked = 0;
      for (std::size_t k = 0; k < 3; ++k)
        if (rows[r + k][governs] == "1") {
          ++marked;
          CHECK(std::stod(rows[r + k][value]) == best);
        }
      CHECK(marked == 1);
      ++governingRows;
    }
    CHECK(governingRows * 3 + 1 == int(rows.size()));
    std::filesystem::remove_all(dir.parent_path());
  }

  TEST_CASE("a vertical spectrum the directions cannot take is refused at its field") {
    using namespace spectrum_combinations;
    const auto refused = [](const std::string& row, const std::string& words) {
      const std::string text = kTableFrame + "analyses:\n" + row;
      const DeckError e = test::readingError(text, "table.yaml");
      const std::string message = e.what();
      CAPTURE(message);
      CHECK(message.find("table.yaml") != std::string::npos);
      CHECK(message.find(words) != std::string::npos);
      CHECK(e.place().line == int(std::count(kTableFrame.begin(), kTableFrame.end(), '\n')) + 2);
    };
    refused("  - {type: response-spectrum, spectrum: " + kHorizontalSpectrum + ", vertical_spectrum: " +
                kVerticalSpectrum + ", directions: [x, z]}\n",
            "add y to directions");
    refused("  - {type: response-spectrum, spectrum: " + kVerticalSpectrum + ", vertical_spectrum: " +
                kVerticalSpectrum + ", directions: [x, y]}\n",
            "spectrum is the horizontal one");
    refused("  - {type: response-spectrum, spectrum: " + kHorizontalSpectrum + ", vertical_spectrum: " +
                kHorizontalSpectrum + ", directions: [x, y]}\n",
            "add component: vertical");
    refused("  - {type: response-spectrum, spectrum: " + kHorizontalSpectrum +
                ", vertical_spectrum: {code: EN1998-1, type: 1, component: vertical, ag: 2.5 m}, "
                "directions: [x, y]}\n",
            "ag");
  }
}
