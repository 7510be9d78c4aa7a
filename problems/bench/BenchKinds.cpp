// Bookkeeping every benchmark kind shares (see BenchKinds.hpp).
#include "problems/bench/BenchKinds.hpp"

#include <stdexcept>

#include "fem/solvers/AvailableMemory.hpp"
#include "fem/solvers/HeapReserve.hpp"
#include "fem/timing/Median.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/structure/MatrixExport.hpp"

namespace beamrotor {

void BenchSamples::addStatic(double buildSeconds, const StaticResult& s, BenchReport& report) {
  build_.push_back(buildSeconds);
  assembly_.push_back(s.time.assembly);
  factor_.push_back(s.time.factor);
  solve_.push_back(s.time.solve);
  total_.push_back(s.time.total);
  report.elements = s.size.elements;
  report.dofs = s.size.dofs;
  report.freeDofs = s.size.freeDofs;
  report.factorEntries = s.size.factorEntries;
  report.solver = s.solver;
}

BenchTimings BenchSamples::medians() const {
  return {median(build_), median(assembly_), median(factor_),
          median(solve_), median(total_),    median(modal_)};
}

void prepareMemory(const BenchOptions& options, std::size_t bytes) {
  const std::size_t available = availableMemoryBytes();
  if (bytes > available)
    throw std::invalid_argument("this model needs about " + memoryText(double(bytes)) + " but " +
                                memoryText(double(available)) +
                                " are available: use fewer --elements or --dofs");
  if (!options.cold) prefaultHeap(bytes);
}

int modesOrDefault(const BenchOptions& options, int kindDefault) {
  return options.modes < 0 ? kindDefault : options.modes;
}

void exportIfAsked(const BenchOptions& options, const Model& model, BenchReport& report) {
  if (options.exportDir.empty()) return;
  const std::filesystem::path dir = options.exportDir;
  writeDirectoryAtomically(dir, [&](const std::filesystem::path& temporary) {
    for (const auto& file : exportMatrices(model, temporary))
      report.exported.push_back((dir / file.filename()).string());
  });
}

}  // namespace beamrotor
