// The fuzz targets' inputs kept in tests/problems/fuzz_inputs/ (seeds, and every finding once
// fixed, named finding_*), replayed through the very code the fuzzers run
// (problems/FuzzInputs.hpp): each must end with the reader's own answer, nothing else.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "problems/FuzzInputs.hpp"
#include "tests/problems/DeckTestSupport.hpp"

namespace {

std::string inputText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_SUITE("fuzz inputs") {
  TEST_CASE("every kept fuzz input is answered without a crash or a stray exception") {
    const auto dir = std::filesystem::path(BEAMROTOR_SOURCE_DIR) / "tests/problems/fuzz_inputs";
    int replayed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string ext = entry.path().extension().string();
      CAPTURE(entry.path().filename().string());
      if (ext == ".deck")
        CHECK_NOTHROW(beamrotor::fuzz::deckInput(inputText(entry.path())));
      else if (ext == ".options")
        CHECK_NOTHROW(beamrotor::fuzz::optionsInput(inputText(entry.path())));
      else
        continue;
      ++replayed;
    }
    CHECK(replayed >= 5);
  }
}
