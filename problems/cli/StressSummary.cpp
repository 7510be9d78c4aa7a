#include "problems/cli/StressSummary.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/output/structure/LineSampling.hpp"

namespace beamrotor::cli {

namespace {

/// The deck's segment holding station x of a beam with section `section` (the section tells
/// the two sides of a step apart); the section's name if none matches.
std::string segmentAt(const Deck& deck, double x, const std::string& section) {
  double start = 0;
  for (std::size_t i = 0; i < deck.segments.size(); ++i) {
    const DeckSegment& s = deck.segments[i];
    const double end = start + s.length, slack = 1e-9 * (1 + end);
    if (x >= start - slack && x <= end + slack && s.sectionName == section)
      return s.name.empty() ? "segment " + std::to_string(i + 1) : s.name;
    start = end;
  }
  return section;
}

/// The largest stress of one kind and the run it belongs to.
struct Peak {
  std::size_t run = 0;
  LinePeak peak;
  bool found = false;  ///< false: no beams
};

/// Largest normal (first) and shear (second) stress among a solution's exact element peaks.
std::pair<Peak, Peak> peaksOf(const Model& model, const std::vector<ElementPeaks>& peaks,
                              std::size_t run) {
  std::pair<Peak, Peak> out;
  if (const auto top = largestAlongLine(model, peaks, &ElementPeaks::stress))
    out.first = {run, *top, true};
  if (const auto top = largestAlongLine(model, peaks, &ElementPeaks::shear))
    out.second = {run, *top, true};
  return out;
}

/// "  largest normal stress 12.3 MPa at x = 0.575 m (rod)" without the line's end; a value at or
/// below `floor` as 0, without a place.
void printPeak(std::ostream& out, const char* what, const Deck& deck, const Model& model,
               const Peak& p, double floor, const std::string& indent,
               const OutputUnits& units) {
  const LineElement& line = *asLine(model.elements()[p.peak.place.element]);
  const double value = zeroAtOrBelow(p.peak.value, floor);
  out << indent << "largest " << what << " " << valueText(value, "Pa", units, {1e-6, "MPa"});
  if (value == 0) return;
  out << " at ";
  if (const auto member = memberLocation(model, p.peak.place.element, p.peak.place.s)) {
    out << valueText(member->second, "m", units) << " along member "
        << model.members()[member->first].first << " (" << line.section().name << ")";
    return;
  }
  out << "x = " << valueText(p.peak.place.x, "m", units) << " ("
      << segmentAt(deck, p.peak.place.x, line.section().name) << ")";
}

const StaticResult* firstStatic(const RunResult& r) {
  for (const AnalysisOutcome& a : r.analyses)
    if (const StaticResult* s = staticsOf(a)) return s;
  return nullptr;
}

}  // namespace

void printStressPeaks(std::ostream& out, const Deck& deck, const Model& model,
                      const std::vector<ElementPeaks>& peaks, const NoiseFloor& floor,
                      const std::string& indent, const OutputUnits& units) {
  const auto [normal, shear] = peaksOf(model, peaks, 0);
  if (!normal.found) return;  // no beams
  printPeak(out, "normal stress", deck, model, normal, floor.stress, indent, units);
  out << "\n";
  printPeak(out, "shear stress ", deck, model, shear, floor.stress, indent, units);
  out << "\n";
}

void printSweepStressPeaks(std::ostream& out, const Deck& deck, const SweepResult& sweep,
                           const OutputUnits& units) {
  Peak normal, shear;
  for (std::size_t k = 0; k < sweep.runs.size(); ++k)
    if (const StaticResult* s = firstStatic(sweep.runs[k])) {
      const auto [n, t] =
          peaksOf(*sweep.runs[k].model, elementPeaks({*sweep.runs[k].model, s->displacement}), k);
      if (n.found && (!normal.found || n.peak.value > normal.peak.value)) normal = n;
      if (t.found && (!shear.found || t.peak.value > shear.peak.value)) shear = t;
    }
  // Round-off against the largest stress of the sweep (NoiseFloor.hpp's rule).
  const double floor =
      kNegligibleShare * std::max(std::abs(normal.peak.value), std::abs(shear.peak.value));
  for (const auto& [what, peak] :
       {std::pair{"normal stress", &normal}, std::pair{"shear stress ", &shear}}) {
    if (!peak->found) continue;
    printPeak(out, what, deck, *sweep.runs[peak->run].model, *peak, floor, "  ", units);
    if (std::abs(peak->peak.value) > floor)
      out << " at " << sweep.parameter << " = "
          << valueText(sweep.values[peak->run], sweep.unit, units);
    out << "\n";
  }
}

}  // namespace beamrotor::cli
