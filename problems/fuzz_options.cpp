// libFuzzer target for the command-line values (--set, --sweep, expressions, --formulation,
// check quantities) against a small deck; see problems/FuzzInputs.hpp. Build and run:
// `make fuzz`.
#include <cstddef>
#include <cstdint>
#include <string>

#include "problems/FuzzInputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  beamrotor::fuzz::optionsInput(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
