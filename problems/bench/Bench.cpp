#include "problems/bench/Bench.hpp"

#include <sys/resource.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "fem/assembly/ParallelParts.hpp"
#include "problems/bench/BenchKinds.hpp"

namespace beamrotor {

namespace {

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

/// Anonymous memory now on transparent huge pages (AnonHugePages of /proc/self/smaps_rollup),
/// MB; 0 where the file is missing.
double hugePagesMb() {
  std::ifstream rollup("/proc/self/smaps_rollup");
  std::string field;
  double kilobytes = 0;
  while (rollup >> field)
    if (field == "AnonHugePages:" && rollup >> kilobytes) return kilobytes / 1024.0;
  return 0;
}

}  // namespace

double BenchReport::figure(const std::string& key) const {
  for (const BenchFigure& f : figures)
    if (f.key == key) return f.value;
  throw std::out_of_range("bench " + options.kind + " has no figure " + key);
}

BenchReport runBench(const BenchOptions& options) {
  BenchReport report;
  if (options.kind == "planar")
    report = benchPlanar(options);
  else if (options.kind == "grid3d")
    report = benchGrid(options);
  else if (options.kind == "rotor")
    report = benchRotor(options);
  else if (options.kind == "frame3d")
    report = benchFrame(options);
  else
    throw std::invalid_argument("bench kind '" + options.kind +
                                "' is not available (available: planar, grid3d, rotor, frame3d)");
  report.options = options;
  report.peakRssMb = peakRssMb();
  report.hugePagesMb = hugePagesMb();
  report.threads = usableCores();
  return report;
}

std::string benchJson(const BenchReport& r) {
  nlohmann::json j;
  j["kind"] = r.options.kind;
  j["elements"] = r.elements;
  j["dofs"] = r.dofs;
  j["free_dofs"] = r.freeDofs;
  j["repeat"] = r.options.repeat;
  j["cold"] = r.options.cold;
  j["solver"] = r.solver;
  j["factor_entries"] = r.factorEntries;
  j["build_s"] = r.median.build;
  j["static"] = {{"assembly_s", r.median.assembly}, {"factor_s", r.median.factor},
                 {"solve_s", r.median.solve},       {"total_s", r.median.staticTotal}};
  j["modal"] = {{"total_s", r.median.modalTotal}, {"frequencies_hz", r.frequenciesHz}};
  if (r.median.staticTotal > 0 && !r.frequenciesHz.empty())
    j["modal"]["to_static"] = r.median.modalTotal / r.median.staticTotal;
  j["rel_error_static"] = r.relErrorStatic;
  for (const BenchFigure& f : r.figures) j[nlohmann::json::json_pointer(f.key)] = f.value;
  j["peak_rss_mb"] = r.peakRssMb;
  j["huge_pages_mb"] = r.hugePagesMb;
  j["threads"] = r.threads;
  j["warnings"] = r.warnings;
  if (!r.exported.empty()) j["exported"] = r.exported;
  return j.dump(2);
}

std::string benchTable(const BenchReport& r) {
  std::ostringstream s;
  s << "bench " << r.options.kind << ": " << r.elements << " elements, " << r.dofs << " dofs ("
    << r.freeDofs << " free), medians of " << r.options.repeat << " runs\n"
    << "  build      " << r.median.build << " s\n"
    << "  assembly   " << r.median.assembly << " s\n"
    << "  factor     " << r.median.factor << " s (" << r.solver << ", factor entries "
    << r.factorEntries << ")\n"
    << "  solve      " << r.median.solve << " s\n"
    << "  static     " << r.median.staticTotal << " s total, rel. error " << r.relErrorStatic
    << "\n";
  if (!r.frequenciesHz.empty())
    s << "  " << (r.options.kind == "rotor" ? "campbell   " : "modal      ") << r.median.modalTotal
      << " s, " << r.frequenciesHz.size() << " modes, f1 = " << r.frequenciesHz[0] << " Hz ("
      << r.median.modalTotal / r.median.staticTotal << " x static)\n";
  for (const BenchFigure& f : r.figures) s << "  " << f.label << ": " << f.value << "\n";
  s << "  threads    " << r.threads
    << " (the cores a pass over elements or equations splits over; BEAMROTOR_THREADS)\n";
  s << "  peak RSS   " << r.peakRssMb << " MB (" << r.hugePagesMb
    << " MB on huge pages at the end)\n";
  for (const std::string& w : r.warnings) s << "  warning: " << w << "\n";
  for (const std::string& file : r.exported) s << "  exported   " << file << "\n";
  return s.str();
}

}  // namespace beamrotor
