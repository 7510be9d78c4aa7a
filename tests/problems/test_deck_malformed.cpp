// Every malformed deck under tests/problems/malformed/ is rejected with one line naming the
// file, the line and the field. Each fixture states its expectation in its first line:
//   # expect: line 12: segments[1].length              (a DeckError: bad input)
//   # expect solve error: line 20: analyses[0]         (a DeckSolveError: analysis failed)
#include <doctest/doctest.h>

#include <fstream>
#include <regex>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

struct Expectation {
  bool solveError = false;
  int line = 0;
  std::string field;
};

Expectation expectationOf(const std::filesystem::path& fixture) {
  std::ifstream in(fixture);
  std::string first;
  std::getline(in, first);
  static const std::regex pattern(R"(^# expect( solve error)?: line (\d+): (.+)$)");
  std::smatch m;
  REQUIRE_MESSAGE(std::regex_match(first, m, pattern),
                  fixture.string() << " lacks a '# expect: line N: FIELD' first line");
  return {m[1].matched, std::stoi(m[2]), m[3]};
}

StudyRequest requestFor(const std::filesystem::path& deck) {
  StudyRequest r;
  r.deckPath = deck.string();
  return r;
}

std::vector<std::filesystem::path> fixtures() {
  std::vector<std::filesystem::path> out;
  const auto dir = std::filesystem::path(BEAMROTOR_SOURCE_DIR) / "tests/problems/malformed";
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".yaml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_SUITE("deck errors") {
  TEST_CASE("every malformed deck gets one line naming file, line and field") {
    const auto all = fixtures();
    // The brief asks for at least 30 kinds of mistakes; fewer means fixtures went missing.
    REQUIRE(all.size() >= 30);
    for (const auto& fixture : all) {
      CAPTURE(fixture.filename().string());
      const Expectation want = expectationOf(fixture);
      std::string message;
      bool solveError = false;
      try {
        solveStudy(requestFor(fixture));
        FAIL("no error raised");
      } catch (const DeckError& e) {
        message = e.what();
        CHECK(e.place().line == want.line);
      } catch (const DeckSolveError& e) {
        message = e.what();
        solveError = true;
        CHECK(e.place().line == want.line);
      }
      CAPTURE(message);
      CHECK(solveError == want.solveError);
      CHECK(message.find(fixture.string() + ":" + std::to_string(want.line) + ":") == 0);
      CHECK(message.find(want.field) != std::string::npos);
      CHECK(message.find('\n') == std::string::npos);
    }
  }

  TEST_CASE("an unknown key is answered with the closest allowed one") {
    try {
      solveStudy(
          requestFor(BEAMROTOR_SOURCE_DIR "/tests/problems/malformed/unknown_segment_key.yaml"));
      FAIL("no error raised");
    } catch (const DeckError& e) {
      CHECK(std::string(e.what()).find("did you mean 'length'?") != std::string::npos);
    }
  }

  TEST_CASE("an unsupported structure names the dofs that move") {
    try {
      solveStudy(
          requestFor(BEAMROTOR_SOURCE_DIR "/tests/problems/malformed/unsupported_axial.yaml"));
      FAIL("no error raised");
    } catch (const DeckSolveError& e) {
      // Held in uy and rz only: the whole beam slides along x.
      CHECK(std::string(e.what()).find("ux") != std::string::npos);
      CHECK(std::string(e.what()).find("not fully supported") != std::string::npos);
    }
  }
}
