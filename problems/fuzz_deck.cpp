// libFuzzer target for the deck reader: arbitrary bytes are read as a deck (and, when small
// enough, built into a model); see problems/FuzzInputs.hpp. Build and run: `make fuzz`.
#include <cstddef>
#include <cstdint>
#include <string>

#include "problems/FuzzInputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  beamrotor::fuzz::deckInput(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
