// `beamrotor bench`: times the standard models (medians of repeated runs) and reports their
// accuracy against the exact references, so speed is never bought with wrong answers.
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

struct BenchOptions {
  std::string kind = "planar";  ///< planar (grid3d and rotor: later)
  int elements = 1000;
  int modes = 10;               ///< 0 skips the modal part
  int repeat = 3;
};

/// Medians over the repeats, seconds.
struct BenchTimings {
  double build = 0, assembly = 0, factor = 0, solve = 0, staticTotal = 0, modalTotal = 0;
};

struct BenchReport {
  BenchOptions options;
  int elements = 0, dofs = 0;
  double factorEntries = 0;          ///< LU fill of the static factorisation
  BenchTimings median;
  double midspanW = 0, exactMidspanW = 0, relErrorStatic = 0;
  std::vector<double> frequenciesHz;
  double exactLowestHz = 0, relErrorLowestHz = 0;
  double peakRssMb = 0;
};

/// Runs the benchmark. Throws std::invalid_argument for an unknown kind.
BenchReport runBench(const BenchOptions& options);

/// The report as JSON text (fields documented in README: static.assembly_s, ...).
std::string benchJson(const BenchReport& report);

/// A short human table.
std::string benchTable(const BenchReport& report);

}  // namespace beamrotor
