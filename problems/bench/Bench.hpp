// `beamrotor bench`: times the standard models (medians of repeated runs) and reports their
// accuracy against exact references, so speed is never bought with wrong answers.
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

struct BenchOptions {
  /// planar, grid3d or rotor (StandardModels.hpp), or frame3d (a building frame run as a deck,
  /// BenchFrame.cpp)
  std::string kind = "planar";
  int elements = 1000;          ///< model size, unless dofs > 0
  /// Lowest modes (rotor: lines of the Campbell diagram); -1 the kind's default (10, rotor
  /// 12); 0 skips the modal part.
  int modes = -1;
  int repeat = 3;
  long long dofs = 0;           ///< > 0: the size whose free dof count is nearest this
  int members = 0;              ///< frame3d: > 0, the member count to come nearest
  int combinations = 0;         ///< frame3d: load combinations of its three load cases
  std::string exportDir;        ///< not empty: write K, M and f there (Matrix Market)
  /// As a user's `solve` runs: the heap is not populated before each run (prepareMemory),
  /// so first-touch page faults fall inside the timings.
  bool cold = false;
};

/// Medians over the repeats, seconds. For rotor, modalTotal is the Campbell diagram.
struct BenchTimings {
  double build = 0, assembly = 0, factor = 0, solve = 0, staticTotal = 0, modalTotal = 0;
};

/// A kind-specific figure (an accuracy or what the kind measures): `key` is its JSON pointer
/// (e.g. "/midspan_w", "/modal/rel_error_lowest"), `label` its line in the table.
struct BenchFigure {
  std::string key;
  double value = 0;
  std::string label;
};

struct BenchReport {
  BenchOptions options;
  int elements = 0, dofs = 0, freeDofs = 0;  ///< dofs: free and constrained
  double factorEntries = 0;                  ///< entries of the static factor (fill-in)
  std::string solver;                        ///< the static direct method and ordering
  BenchTimings median;
  std::vector<double> frequenciesHz;         ///< rotor: natural frequencies at rest
  double relErrorStatic = 0;                 ///< the kind's exact static reference
  std::vector<BenchFigure> figures;
  double peakRssMb = 0;
  double hugePagesMb = 0;                    ///< of the memory held at the end (MB)
  int threads = 1;                           ///< cores a pass may split over (usableCores)
  std::vector<std::string> exported;         ///< files written by --export
  std::vector<std::string> warnings;         ///< from the analyses (e.g. skipped modes)

  /// The figure at `key`; throws std::out_of_range when the kind has none.
  double figure(const std::string& key) const;
};

/// Runs the benchmark. Throws std::invalid_argument for an unknown kind or a bad size.
BenchReport runBench(const BenchOptions& options);

/// The report as JSON text (fields documented in README: static.assembly_s, ...).
std::string benchJson(const BenchReport& report);

/// A short human table.
std::string benchTable(const BenchReport& report);

}  // namespace beamrotor
