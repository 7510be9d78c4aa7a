// The fuzz targets' inputs kept in tests/problems/fuzz_inputs/ (seeds, and every finding once
// fixed, named finding_*), replayed through the very code the fuzzers run
// (problems/FuzzInputs.hpp): each must end with the reader's own answer, nothing else.
#include <doctest/doctest.h>

#include "problems/FuzzInputs.hpp"
#include "tests/problems/DeckTestSupport.hpp"

TEST_SUITE("fuzz inputs") {
  TEST_CASE("every kept fuzz input is answered without a crash or a stray exception") {
    const auto dir = std::filesystem::path(BEAMROTOR_SOURCE_DIR) / "tests/problems/fuzz_inputs";
    int replayed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string ext = entry.path().extension().string();
      CAPTURE(entry.path().filename().string());
      if (ext == ".deck")
        CHECK_NOTHROW(beamrotor::fuzz::deckInput(beamrotor::test::fileContents(entry.path())));
      else if (ext == ".options")
        CHECK_NOTHROW(beamrotor::fuzz::optionsInput(beamrotor::test::fileContents(entry.path())));
      else
        continue;
      ++replayed;
    }
    CHECK(replayed >= 5);
  }
}
