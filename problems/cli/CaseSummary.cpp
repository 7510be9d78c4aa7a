// The summary of load cases and combinations (see CaseSummary.hpp).
#include "problems/cli/CaseSummary.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "problems/cli/MemberSummary.hpp"
#include "problems/cli/SolutionSummary.hpp"
#include "problems/cli/StressSummary.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/output/structure/Reactions.hpp"

namespace beamrotor::cli {

namespace {

/// "case 'dead'" or "combination 'ULS' = 1.35 dead + 1.5 live1".
std::string caseTitle(const CaseOutcome& c) {
  std::string title = c.combination ? "combination '" : "case '";
  title += c.name;
  title += "'";
  for (std::size_t i = 0; i < c.factors.size(); ++i) {
    title += i ? " + " : " = ";
    title += formatValue(c.factors[i].second);
    title += " ";
    title += c.factors[i].first;
  }
  return title;
}

/// One case in full: reactions, point displacements, stresses, members, warnings.
void printCase(std::ostream& out, const Deck& deck, const RunResult& run, const CaseOutcome& c,
               const StaticExtremes& x, const OutputUnits& units) {
  out << "    " << caseTitle(c) << ":\n";
  const NoiseFloor floor = noiseFloorOf(*run.model, c.statics, &x);
  printReactions(out, c.statics, floor, "      ", units);
  printPointDisplacements(out, deck, run, c.statics, floor, "      ", units);
  printStressPeaks(out, deck, *run.model, x.peaks, floor, "      ", units);
  printMemberExtremes(out, deck, *run.model, x, floor, "      ", units);
  for (const std::string& w : c.warnings) out << "      warning: " << w << "\n";
}

/// One case on one line: its largest displacement (a frame) and normal stress.
void printCaseLine(std::ostream& out, const Model& model, const CaseOutcome& c,
                   const StaticExtremes& x, const OutputUnits& units) {
  out << "    " << padded(caseTitle(c), 30);
  if (!model.members().empty())
    out << "largest displacement "
        << padded(valueText(x.largestDisplacement.value, "m", units) + ",", 16);
  if (const auto top = largestPeak(x.peaks, &ElementPeaks::stress))
    out << "largest normal stress " << valueText(top->value, "Pa", units, {1e-6, "MPa"});
  out << (c.warnings.empty() ? "" : " (warning: see results.json)") << "\n";
}

/// "value unit [combination]"; the unit left out when `named` is false (a header names it).
/// `value` is g's value as shown, 0 when it is round-off; a 0 names no combination (every
/// combination gives it).
std::string governed(const Governed& g, double value, const std::vector<CaseOutcome>& cases,
                     const OutputUnits::Shown& shown, bool named = true) {
  std::string out = formatValue(value * shown.factor);
  if (named && !shown.unit.empty()) out += " " + shown.unit;
  if (value == 0) return out;
  out += " [";
  out += cases.at(std::size_t(g.by)).name;
  return out + "]";
}

/// The envelope of reactions or of springs' forces, one line per support or spring (the first
/// kSummarySupports).
void printEnvelopeForces(std::ostream& out, const std::string& title,
                         const std::vector<std::pair<ReactionComponent, GovernedRange>>& forces,
                         const std::vector<CaseOutcome>& cases, const NoiseFloor& floor,
                         const OutputUnits& units) {
  const OutputUnits::Shown force = units.valueIn("N", {1, "N"});
  const OutputUnits::Shown moment = units.valueIn("N m", {1, "N m"});
  out << "    " << title << " (" << force.unit << ", " << moment.unit << "):\n";
  std::string name;
  std::size_t names = 0;
  for (const auto& [r, range] : forces) {
    if (r.support != name) {
      if (++names > kSummarySupports) break;
      out << (name.empty() ? "" : "\n") << "      " << padded(r.support, 12);
      name = r.support;
    }
    const OutputUnits::Shown& shown = isRotation(r.dof) ? moment : force;
    const auto text = [&](const Governed& g) {
      return governed(g, floor.load(g.value, isRotation(r.dof)), cases, shown, false);
    };
    out << padded(std::string(reactionName(r.dof)) + " " + text(range.max) + " / " +
                      text(range.min),
                  46);
  }
  if (!name.empty()) out << "\n";
}

/// The envelope over the combinations, each value with the combination that governs it.
void printEnvelope(std::ostream& out, const Deck& deck, const RunResult& run,
                   const std::vector<CaseOutcome>& cases, const CaseEnvelope& e,
                   const OutputUnits& units) {
  const Model& model = *run.model;
  double roundOff = 0;
  for (const CaseOutcome& c : cases) roundOff = std::max(roundOff, c.statics.roundOff);
  const NoiseFloor floor = noiseFloorOf(model, e, roundOff);
  out << "  envelope over the combinations (largest and smallest, the governing combination in "
         "brackets):\n";
  if (e.largestDisplacement.by >= 0)
    out << "    largest displacement "
        << governed(e.largestDisplacement, e.largestDisplacement.value, cases,
                    units.valueIn("m", {1, "m"}))
        << "\n";
  if (e.largestStress.by >= 0)
    out << "    largest normal stress "
        << governed(e.largestStress, e.largestStress.value, cases,
                    units.valueIn("Pa", {1e-6, "MPa"}))
        << "\n";
  if (!e.reactions.empty() || e.springs.empty())
    printEnvelopeForces(out, "reactions", e.reactions, cases, floor, units);
  if (!e.springs.empty())
    printEnvelopeForces(out, "springs and bearings", e.springs, cases, floor, units);
  if (e.members.empty()) return;
  // The members of the largest bending moments, as the member lines of a case.
  const std::vector<ForceComponent> shown =
      deck.dimension == "planar"
          ? std::vector<ForceComponent>{ForceComponent::N, ForceComponent::Vy, ForceComponent::Mz}
          : std::vector<ForceComponent>(kForceComponents.begin(), kForceComponents.end());
  const auto moment = [&](std::size_t m) {
    double largest = 0;
    for (ForceComponent f : {ForceComponent::Mz, ForceComponent::My})
      largest = std::max({largest, std::abs(e.members[m][int(f)].max.value),
                          std::abs(e.members[m][int(f)].min.value)});
    return largest;
  };
  std::vector<std::size_t> listed(e.members.size());
  std::iota(listed.begin(), listed.end(), std::size_t{0});
  if (listed.size() > kSummaryMembers) {
    std::stable_sort(listed.begin(), listed.end(),
                     [&](std::size_t a, std::size_t b) { return moment(a) > moment(b); });
    listed.resize(kSummaryMembers);
    std::sort(listed.begin(), listed.end());
  }
  const OutputUnits::Shown force = units.valueIn("N", {1, "N"});
  const OutputUnits::Shown torque = units.valueIn("N m", {1, "N m"});
  out << "    members (largest / smallest along each; " << force.unit << ", " << torque.unit << ")";
  if (listed.size() < e.members.size())
    out << ", the " << listed.size() << " of the largest bending moment among "
        << e.members.size();
  out << ":\n";
  for (std::size_t m : listed) {
    out << "      " << model.members()[m].first << ":";
    for (ForceComponent f : shown) {
      const OutputUnits::Shown& unit = isMomentComponent(f) ? torque : force;
      const auto text = [&](const Governed& g) {
        return governed(g, floor.load(g.value, isMomentComponent(f)), cases, unit, false);
      };
      out << "  " << componentName(f) << " " << text(e.members[m][int(f)].max) << " / "
          << text(e.members[m][int(f)].min);
    }
    out << "\n";
  }
}

}  // namespace

void printCases(std::ostream& out, const Deck& deck, const RunResult& run,
                const AnalysisOutcome& a, const AnalysisExtremes& extremes,
                const OutputUnits& units) {
  const std::vector<CaseOutcome>& cases = casesOf(a);
  if (cases.empty()) return;
  out << "  load cases and combinations (" << cases.size() << "):\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases.size() <= kSummaryCases)
      printCase(out, deck, run, cases[i], extremes.cases.at(i), units);
    else
      printCaseLine(out, *run.model, cases[i], extremes.cases.at(i), units);
  }
  const CaseEnvelope envelope = caseEnvelope(*run.model, cases, extremes.cases, extremes.canGovern);
  if (!envelope.empty()) printEnvelope(out, deck, run, cases, envelope, units);
}

}  // namespace beamrotor::cli
