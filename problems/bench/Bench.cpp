#include "problems/bench/Bench.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "fem/HeapReserve.hpp"
#include "fem/Modal.hpp"
#include "fem/Static.hpp"
#include "fem/Stopwatch.hpp"
#include "problems/bench/StandardModels.hpp"

namespace beamrotor {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

}  // namespace

BenchReport runBench(const BenchOptions& options) {
  if (options.kind != "planar")
    throw std::invalid_argument("bench kind '" + options.kind +
                                "' is not available (available: planar)");
  if (options.elements < 10) throw std::invalid_argument("bench needs at least 10 elements");
  BenchReport report;
  report.options = options;
  std::vector<double> build, assembly, factor, solve, total, modal;
  for (int run = 0; run < std::max(1, options.repeat); ++run) {
    prefaultHeap(estimatedStaticBytes(options.elements, 3));
    Stopwatch clock;
    const PlanarBenchModel bench = planarBenchModel(options.elements);
    build.push_back(clock.lap());
    const StaticResult s = solveStatic(*bench.model);
    assembly.push_back(s.time.assembly);
    factor.push_back(s.time.factor);
    solve.push_back(s.time.solve);
    total.push_back(s.time.total);
    report.elements = s.size.elements;
    report.dofs = s.size.dofs;
    report.factorEntries = s.size.factorEntries;
    report.midspanW = s.displacement(bench.midspanNode, dofIndex(Dof::uy));
    report.exactMidspanW = bench.exactMidspanW;
    report.exactLowestHz = bench.exactLowestHz;
    if (options.modes > 0) {
      const ModalResult m = solveModes(*bench.model, {options.modes, 0});
      modal.push_back(m.time.total);
      report.frequenciesHz.clear();
      for (const Mode& mode : m.modes) report.frequenciesHz.push_back(mode.frequencyHz);
    }
  }
  report.median = {median(build), median(assembly), median(factor),
                   median(solve), median(total),    median(modal)};
  report.relErrorStatic = std::abs(report.midspanW / report.exactMidspanW - 1);
  if (!report.frequenciesHz.empty())
    report.relErrorLowestHz = std::abs(report.frequenciesHz[0] / report.exactLowestHz - 1);
  report.peakRssMb = peakRssMb();
  return report;
}

std::string benchJson(const BenchReport& r) {
  nlohmann::json j;
  j["kind"] = r.options.kind;
  j["elements"] = r.elements;
  j["dofs"] = r.dofs;
  j["repeat"] = r.options.repeat;
  j["factor_entries"] = r.factorEntries;
  j["build_s"] = r.median.build;
  j["static"] = {{"assembly_s", r.median.assembly}, {"factor_s", r.median.factor},
                 {"solve_s", r.median.solve},       {"total_s", r.median.staticTotal}};
  j["modal"] = {{"total_s", r.median.modalTotal}, {"frequencies_hz", r.frequenciesHz},
                {"exact_lowest_hz", r.exactLowestHz},
                {"rel_error_lowest", r.relErrorLowestHz}};
  j["midspan_w"] = r.midspanW;
  j["exact_midspan_w"] = r.exactMidspanW;
  j["rel_error_static"] = r.relErrorStatic;
  j["peak_rss_mb"] = r.peakRssMb;
  return j.dump(2);
}

std::string benchTable(const BenchReport& r) {
  std::ostringstream s;
  s << "bench " << r.options.kind << ": " << r.elements << " elements, " << r.dofs
    << " dofs, medians of " << r.options.repeat << " runs\n"
    << "  build      " << r.median.build << " s\n"
    << "  assembly   " << r.median.assembly << " s\n"
    << "  factor     " << r.median.factor << " s (LU entries " << r.factorEntries << ")\n"
    << "  solve      " << r.median.solve << " s\n"
    << "  static     " << r.median.staticTotal << " s total, midspan w = " << r.midspanW
    << " m, rel. error " << r.relErrorStatic << "\n";
  if (!r.frequenciesHz.empty())
    s << "  modal      " << r.median.modalTotal << " s for " << r.frequenciesHz.size()
      << " modes, f1 = " << r.frequenciesHz[0] << " Hz, " << r.relErrorLowestHz
      << " above the continuous span (discrete model: 6.7e-6)\n";
  s << "  peak RSS   " << r.peakRssMb << " MB\n";
  return s.str();
}

}  // namespace beamrotor
