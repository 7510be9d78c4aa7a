// The benchmark of each standard model, and the bookkeeping they share: per-run samples and
// their medians, and the export of the model's matrices. Bench.cpp picks one by kind.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/bench/Bench.hpp"

namespace beamrotor {

BenchReport benchPlanar(const BenchOptions& options);
BenchReport benchGrid(const BenchOptions& options);
BenchReport benchRotor(const BenchOptions& options);
BenchReport benchFrame(const BenchOptions& options);

/// Collects one bench's per-run times; the report keeps their medians.
class BenchSamples {
 public:
  /// One run's model build (s) and static solve; also records the sizes and the solver.
  void addStatic(double buildSeconds, const StaticResult& s, BenchReport& report);
  /// One run's modal part (s).
  void addModal(double seconds) { modal_.push_back(seconds); }
  BenchTimings medians() const;

 private:
  std::vector<double> build_, assembly_, factor_, solve_, total_, modal_;
};

/// Before each run: refuses a model whose estimated memory (`bytes`) is more than the process
/// can have (std::invalid_argument with the estimate and what is available); otherwise makes
/// that memory ready (prefaultHeap), unless options.cold.
void prepareMemory(const BenchOptions& options, std::size_t bytes);

/// The kind's modes when options.modes is -1.
int modesOrDefault(const BenchOptions& options, int kindDefault);

/// Writes the model's matrices to options.exportDir (when set) and lists them in the report.
void exportIfAsked(const BenchOptions& options, const Model& model, BenchReport& report);

}  // namespace beamrotor
