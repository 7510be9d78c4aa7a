// The frame3d benchmark: a building frame of n x n bays and n storeys written as a deck and
// run as `beamrotor solve` runs it (deck read, model, static analysis with its load cases and
// combinations, every output written: results.json, CSV, VTK, charts), each phase timed, with
// the whole run's time per member. Exact references, independent of the discretisation:
// equilibrium of the whole frame. The vertical reactions sum to its weight (rho A g over the
// members' length) and the horizontal ones to minus the wind loads, under `loads:` and under
// every combination (the factored weight and wind), to round-off.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "fem/timing/Median.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "problems/bench/BenchKinds.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/output/Output.hpp"
#include "problems/run/DeckRunner.hpp"

namespace beamrotor {

namespace {

/// The frame: bays of 4 m (x) by 5 m (z), storeys of 3.5 m (y, up); steel tube columns
/// (D 0.3 m, t 12 mm) and rectangular beams (0.2 x 0.4 m), 5 elements per member; every base
/// clamped; self-weight and a wind load of 10 kN along x at every top joint.
struct FrameBenchData {
  static constexpr double bayX = 4, bayZ = 5, storey = 3.5, wind = 1e4, g = 9.81;
  static constexpr double rho = 7850;
  static constexpr double columnD = 0.3, columnT = 0.012, beamB = 0.2, beamH = 0.4;
  static constexpr int elements = 5;
};

/// Members of the frame of n bays each way and n storeys: n + 1 squared columns per storey,
/// and per floor 2 n (n + 1) beams.
long long frameMembers(int n) {
  const long long side = n + 1;
  return n * (side * side + 2LL * n * side);
}

/// The bay count whose member count is nearest `members`.
int frameBays(int members) {
  int best = 1;
  for (int n = 1; frameMembers(n) < 4LL * members; ++n)
    if (std::abs(frameMembers(n) - members) < std::abs(frameMembers(best) - members)) best = n;
  return best;
}

/// A combination's factors on the three cases (dead, wind along x, wind along z): the dead
/// load between 1 and 1.35, the winds in steps between -1.5 and 1.5.
std::array<double, 3> combinationFactors(int k) {
  return {1 + 0.35 * (k % 8) / 7, 1.5 * ((k % 7) - 3) / 3, 1.5 * ((k % 5) - 2) / 2};
}

/// "n3_0_2", or with another prefix a member's name from its first joint ("c3_0_2"); appended
/// piece by piece (GCC 12 takes "literal" + a temporary string for an overlapping copy).
std::string joint(int i, int j, int k, const char* prefix = "n") {
  std::string out = prefix;
  for (int v : {i, j, k}) {
    if (out.size() > 1) out += '_';
    out += std::to_string(v);
  }
  return out;
}

/// The deck text of the frame with `combinations` combinations of its three load cases.
std::string frameDeck(int n, int combinations) {
  using D = FrameBenchData;
  std::ostringstream d;
  d.precision(17);
  d << "title: frame3d bench, " << n << " bays each way, " << n << " storeys\n"
    << "model: {dimension: 3d}\n"
    << "materials: [{name: steel, E: 210e9, nu: 0.3, rho: " << D::rho << "}]\n"
    << "sections:\n"
    << "  - {name: column, shape: tube, D: " << D::columnD << ", t: " << D::columnT << "}\n"
    << "  - {name: beam, shape: rectangle, b: " << D::beamB << ", h: " << D::beamH << "}\n"
    << "nodes:\n";
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        d << "  - {name: " << joint(i, j, k) << ", at: [" << D::bayX * i << ", " << D::storey * k
          << ", " << D::bayZ * j << "]}\n";
  d << "members:\n";
  const auto member = [&](const std::string& name, const std::string& from,
                          const std::string& to, const char* section) {
    d << "  - {name: " << name << ", from: " << from << ", to: " << to << ", section: " << section
      << ", elements: " << D::elements << "}\n";
  };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        member(joint(i, j, k, "c"), joint(i, j, k), joint(i, j, k + 1), "column");
  for (int k = 1; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        if (i < n) member(joint(i, j, k, "x"), joint(i, j, k), joint(i + 1, j, k), "beam");
        if (j < n) member(joint(i, j, k, "z"), joint(i, j, k), joint(i, j + 1, k), "beam");
      }
  d << "supports:\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      d << "  - {name: " << joint(i, j, 0, "s") << ", at: " << joint(i, j, 0) << ", fix: clamped}\n";
  const auto wind = [&](const char* component) {
    std::string out = "[";
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        out += (i || j) ? ", " : "";
        out += "{type: point, at: ";
        out += joint(i, j, n);
        out += ", ";
        out += component;
        out += ": ";
        out += std::to_string(int(D::wind));
        out += "}";
      }
    return out + "]";
  };
  d << "loads: [{type: self-weight, g: " << D::g << "}]\n";
  if (combinations > 0) {
    d << "load_cases:\n"
      << "  - {name: dead, loads: [{type: self-weight, g: " << D::g << "}]}\n"
      << "  - {name: wind_x, loads: " << wind("fx") << "}\n"
      << "  - {name: wind_z, loads: " << wind("fz") << "}\n"
      << "combinations:\n";
    for (int k = 0; k < combinations; ++k) {
      const auto f = combinationFactors(k);
      d << "  - {name: C" << k + 1 << ", factors: {dead: " << f[0] << ", wind_x: " << f[1]
        << ", wind_z: " << f[2] << "}}\n";
    }
  }
  d << "analyses: [{type: static}]\n";
  return d.str();
}

/// The frame's weight (N): rho A g over every member's length.
double frameWeight(int n) {
  using D = FrameBenchData;
  const double pi = std::numbers::pi;
  const double columnA =
      pi / 4 * (D::columnD * D::columnD - std::pow(D::columnD - 2 * D::columnT, 2));
  const double beamA = D::beamB * D::beamH;
  const double side = n + 1;
  const double columns = n * side * side * D::storey * columnA;
  const double beams = n * side * n * (D::bayX + D::bayZ) * beamA;
  return D::rho * D::g * (columns + beams);
}

/// The largest relative departure from equilibrium of a solution's reactions under the
/// weight times `dead` and the wind along x and z times `windX`, `windZ`.
double equilibriumError(const StaticResult& s, int n, double dead, double windX, double windZ) {
  const double side = n + 1, weight = dead * frameWeight(n);
  const double wx = windX * side * side * FrameBenchData::wind;
  const double wz = windZ * side * side * FrameBenchData::wind;
  double fx = 0, fy = 0, fz = 0;
  for (const ReactionComponent& r : s.reactions) {
    if (r.dof == Dof::ux) fx += r.value;
    if (r.dof == Dof::uy) fy += r.value;
    if (r.dof == Dof::uz) fz += r.value;
  }
  const double scale = std::abs(weight) + std::abs(wx) + std::abs(wz);
  return std::max({std::abs(fy - weight), std::abs(fx + wx), std::abs(fz + wz)}) / scale;
}

}  // namespace

BenchReport benchFrame(const BenchOptions& options) {
  const int n = frameBays(options.members > 0 ? options.members : options.elements);
  const std::string text = frameDeck(n, options.combinations);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("beamrotor-bench-frame-" + std::to_string(::getpid()));
  BenchReport report;
  BenchSamples samples;
  std::vector<double> read, cases, write, whole;
  double error = 0;
  for (int run = 0; run < std::max(1, options.repeat); ++run) {
    Stopwatch clock, total;
    const Deck deck = readDeck(parseDeckText(text, "frame3d_bench.yaml"));
    read.push_back(clock.lap());
    const RunResult result = runDeck(deck);
    const AnalysisOutcome& a = result.analyses.front();
    const StaticResult& s = *staticsOf(a);
    samples.addStatic(result.modelSeconds, s, report);
    double caseSeconds = 0;
    for (const CaseOutcome& c : casesOf(a)) caseSeconds += c.statics.time.total;
    cases.push_back(caseSeconds);
    clock.lap();
    writeRunOutputs(result, dir);
    write.push_back(clock.lap());
    whole.push_back(total.lap());
    error = equilibriumError(s, n, 1, 0, 0);
    for (const CaseOutcome& c : casesOf(a)) {
      if (!c.combination) continue;
      const auto f = combinationFactors(std::stoi(c.name.substr(1)) - 1);
      error = std::max(error, equilibriumError(c.statics, n, f[0], f[1], f[2]));
    }
  }
  std::filesystem::remove_all(dir);
  report.median = samples.medians();
  report.relErrorStatic = error;
  const double members = double(frameMembers(n));
  report.figures = {
      {"/frame/members", members, "members"},
      {"/frame/combinations", double(options.combinations), "combinations"},
      {"/frame/read_s", median(read), "deck read (s)"},
      {"/frame/cases_s", median(cases), "load cases and combinations solved (s)"},
      {"/frame/cases_to_static", median(cases) / report.median.staticTotal,
       "their time over the static solve's"},
      {"/frame/write_s", median(write), "outputs prepared and written, charts drawn (s)"},
      {"/frame/whole_s", median(whole), "whole run: read, solve, write (s)"},
      {"/frame/per_member_us", median(whole) / members * 1e6, "whole run per member (us)"}};
  return report;
}

}  // namespace beamrotor
