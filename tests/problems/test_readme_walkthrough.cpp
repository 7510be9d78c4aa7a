// The README's first deck, as a reader would follow it: its YAML pieces put in one file, solved,
// and every line of the output the README shows found in what beamrotor prints. A change to
// the summary or the deck format that the README does not follow fails here. The numbers it
// shows are also checked against beam theory, independently of the deck's own checks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor {

namespace {

/// The fenced blocks of `language` between the lines starting `from` and `to`, in order.
std::vector<std::string> fencedBlocks(const std::string& text, const std::string& from,
                                      const std::string& to, const std::string& language) {
  std::vector<std::string> blocks;
  std::istringstream lines(text);
  bool inside = false, inBlock = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(from, 0) == 0) inside = true;
    if (inside && line.rfind(to, 0) == 0 && !inBlock) break;
    if (!inside) continue;
    if (!inBlock && line == "```" + language) {
      inBlock = true;
      blocks.emplace_back();
    } else if (inBlock && line == "```") {
      inBlock = false;
    } else if (inBlock) {
      blocks.back() += line + "\n";
    }
  }
  return blocks;
}

std::string withoutTrailingBlanks(std::string line) {
  while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
  return line;
}

/// A check line as compared: without trailing blanks, and a relative error below 1e-12 (the
/// round-off of an exact method, whose digits differ from one BLAS build or processor to
/// another: 2.3e-14 on one machine, 2.7e-14 on the next) written "round-off"; a larger one
/// (a discretisation's error) is compared as printed.
std::string compared(const std::string& line) {
  std::string out = withoutTrailingBlanks(line);
  const std::string key = "rel.err ";
  const std::size_t at = out.find(key);
  if (at == std::string::npos) return out;
  const std::size_t from = at + key.size(), to = out.find(' ', from);
  const std::string value = out.substr(from, to == std::string::npos ? to : to - from);
  char* end = nullptr;
  const double relative = std::strtod(value.c_str(), &end);
  if (end != value.c_str() && relative < 1e-12) out.replace(from, value.size(), "round-off");
  return out;
}

}  // namespace

TEST_SUITE("readme") {
  TEST_CASE("the first deck of the README solves and prints what the README shows") {
    const std::string readme = test::fileContents(std::filesystem::path(BEAMROTOR_SOURCE_DIR) /
                                                  "README.md");
    const auto pieces =
        fencedBlocks(readme, "## A first deck", "**5. Solve it.**", "yaml");
    REQUIRE(pieces.size() == 4);
    const auto shown = fencedBlocks(readme, "**5. Solve it.**", "## Commands", "text");
    REQUIRE(shown.size() == 1);

    const std::filesystem::path dir = test::scratchDir("readme_walkthrough");
    {
      std::ofstream deck(dir / "tube_beam.yaml");
      for (const std::string& piece : pieces) deck << piece << "\n";
    }
    const test::ProcessResult solved = test::runBeamrotor({"solve", "tube_beam.yaml"}, dir);
    CAPTURE(solved.err);
    REQUIRE(solved.exitCode == 0);
    std::vector<std::string> printed;
    std::istringstream out(solved.out);
    for (std::string line; std::getline(out, line);) printed.push_back(compared(line));
    std::istringstream expected(shown.front());
    int lines = 0;
    for (std::string line; std::getline(expected, line); ++lines) {
      CAPTURE(line);
      CHECK(std::find(printed.begin(), printed.end(), compared(line)) != printed.end());
    }
    CHECK(lines >= 10);

    // The figures the README's prose reads off, from beam theory written out here: the
    // deflection under the load P a^2 b^2 / (3 E I L), the reactions P b / L and P a / L, the
    // stress M / W under the load, the first frequency pi / (2 L^2) sqrt(E I / (rho A)).
    const double L = 3, a = 1, b = L - a, P = 5000, D = 0.08, t = 0.005, E = 210e9, rho = 7850;
    const double pi = std::numbers::pi, d = D - 2 * t;
    const double I = pi * (std::pow(D, 4) - std::pow(d, 4)) / 64;
    const double A = pi * (D * D - d * d) / 4;
    CHECK(P * a * a * b * b / (3 * E * I * L) == doctest::Approx(0.0127183).epsilon(1e-5));
    CHECK(P * b / L == doctest::Approx(3333.33).epsilon(1e-5));
    CHECK(P * a / L == doctest::Approx(1666.67).epsilon(1e-5));
    CHECK(P * a * b / L * (D / 2) / I == doctest::Approx(160.25e6).epsilon(1e-5));
    CHECK(pi / (2 * L * L) * std::sqrt(E * I / (rho * A)) ==
          doctest::Approx(23.9901).epsilon(1e-4));
    CHECK(std::filesystem::exists(dir / "out" / "tube_beam" / "static_diagrams.png"));
    std::filesystem::remove_all(dir);
  }
}

}  // namespace beamrotor
