// libFuzzer target for the deck reader: arbitrary bytes are read as a deck (and, when small
// enough, built into a model). The reader must answer every input with a DeckError or a deck;
// any other exception, crash, hang or sanitizer report is a bug. Build and run: `make fuzz`.
#include <cstddef>
#include <cstdint>
#include <string>

#include "problems/deck/DeckError.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/run/ModelBuilder.hpp"

namespace {

/// Models above this many elements are read but not built: building is linear in the element
/// count and the fuzzer's time is better spent on more inputs.
constexpr int kLargestBuilt = 2000;

int elementEstimate(const beamrotor::Deck& deck) {
  double n = double(deck.points.size());
  for (const auto& s : deck.segments) n += s.elements > 0 ? s.elements : s.length / s.size + 1;
  return n > kLargestBuilt ? kLargestBuilt + 1 : int(n);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const beamrotor::DeckSource source = beamrotor::parseDeckText(text, "fuzz.yaml");
    const beamrotor::Deck deck = beamrotor::readDeck(source);
    if (elementEstimate(deck) <= kLargestBuilt) beamrotor::buildModel(deck);
  } catch (const beamrotor::DeckError&) {
    // The reader's own answer to bad input: expected.
  }
  return 0;
}
