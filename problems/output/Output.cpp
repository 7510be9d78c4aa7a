// Placeholder: replaced by the real writers.
#include "problems/output/Output.hpp"

namespace beamrotor {

void writeRunOutputs(const RunResult&, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
}

void writeSweepOutputs(const SweepResult&, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
}

}  // namespace beamrotor
