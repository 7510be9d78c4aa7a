#include "problems/cli/Summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <variant>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/model/DofMap.hpp"
#include "problems/cli/AdequateSummary.hpp"
#include "problems/cli/CaseSummary.hpp"
#include "problems/cli/SolutionSummary.hpp"
#include "problems/cli/CrankSummary.hpp"
#include "problems/cli/MovingSummary.hpp"
#include "problems/cli/MemberSummary.hpp"
#include "problems/cli/RotorSummary.hpp"
#include "problems/cli/SpectrumSummary.hpp"
#include "problems/cli/StabilitySummary.hpp"
#include "problems/cli/StressSummary.hpp"
#include "problems/cli/TorsionSummary.hpp"
#include "problems/cli/TransientSummary.hpp"
#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/output/ShownCheck.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/output/structure/Reactions.hpp"
#include "problems/run/Overloaded.hpp"

namespace beamrotor::cli {

namespace {

SystemSize sizeOf(const RunResult& run) {
  using Size = std::optional<SystemSize>;
  for (const AnalysisOutcome& a : run.analyses) {
    const Size size = std::visit(
        Overloaded{[](const StaticOutcome& r) -> Size { return r.statics.size; },
                   [](const SecondOrderResult& r) -> Size { return r.secondOrder.size; },
                   [](const ModalResult& r) -> Size { return r.size; },
                   [](const ResponseSpectrumResult& r) -> Size { return r.modal.size; },
                   [](const BucklingResult& r) -> Size { return r.size; },
                   [](const TransientOutcome& r) -> Size { return r.result.size; },
                   [](const RotorModesResult& r) -> Size { return r.size; },
                   [](const CampbellOutcome& r) -> Size { return r.campbell.size; },
                   [](const UnbalanceOutcome& r) -> Size { return r.unbalance.size; },
                   [](const RunUpOutcome& r) -> Size { return r.runUp.size; },
                   [](const FrequencyResponseOutcome& r) -> Size { return r.response.size; },
                   // These keep no system size of the deck's model (a torsion analysis
                   // solves its own, in twist alone): the model line takes it from the
                   // first analysis that does, or from the model itself.
                   [](const TorsionOutcome&) -> Size { return std::nullopt; },
                   [](const RigidBodyOutcome&) -> Size { return std::nullopt; },
                   [](const CriticalSpeedMapOutcome&) -> Size { return std::nullopt; },
                   [](const BearingLoadsOutcome&) -> Size { return std::nullopt; },
                   [](const LevelOneOutcome&) -> Size { return std::nullopt; },
                   [](const CrankSliderOutcome&) -> Size { return std::nullopt; },
                   [](const MovingLoadOutcome&) -> Size { return std::nullopt; },
                   [](const BaseMotionResult&) -> Size { return std::nullopt; }},
        a.result);
    if (size) return *size;
  }
  return systemSize(*run.model, DofMap(*run.model), 0, 0);
}

void printStatic(std::ostream& out, const Deck& deck, const RunResult& run,
                 const AnalysisOutcome& a, const AnalysisExtremes& extremes,
                 const OutputUnits& units) {
  const StaticResult& r = *staticsOf(a);
  char conditioning[64];
  std::snprintf(conditioning, sizeof conditioning, "rcond %.1e, round-off <= %.1e", r.rcond,
                r.roundOff);
  out << "static analysis '" << a.name << "' (" << r.solver << ", " << conditioning << ")\n";
  if (const auto* s = resultOf<StaticOutcome>(a); s && !s->ownLoads) {
    // The solution of the empty `loads:` is all zeros: only the cases say anything.
    out << "  (its `loads:` is empty: the structure is loaded by its load cases alone)\n";
  } else {
    const NoiseFloor floor = noiseFloorOf(*run.model, r, &*extremes.own);
    printReactions(out, r, floor, "  ", units);
    printPointDisplacements(out, deck, run, r, floor, "  ", units);
    if (!r.contacts.empty()) {
      out << "  contacts (after " << r.activeSetIterations << " active-set solves):\n";
      for (const ContactState& k : r.contacts)
        out << "    " << padded(k.name, 12)
            << (k.active ? "closed, " + std::string(isRotation(k.dof) ? "moment " : "force ") +
                               valueText(k.force, isRotation(k.dof) ? "N m" : "N", units)
                         : "open, gap " + valueText(k.gap, motionUnit(k.dof), units))
            << "  (" << dofName(k.dof) << " = " << formatValue(k.value) << ")\n";
    }
    if (!r.oneWayMembers.empty()) {
      out << "  tension-only / compression-only members:\n";
      for (const OneWayMemberState& m : r.oneWayMembers)
        out << "    " << padded(m.name, 12)
            << (m.slack ? "slack, ends " +
                              std::string(m.elongation > 0 ? "apart by " : "closer by ") +
                              valueText(std::abs(m.elongation), "m", units)
                        : "in action, N = " + valueText(m.force, "N", units))
            << "\n";
    }
    printStressPeaks(out, deck, *run.model, extremes.own->peaks, floor, "  ", units);
    printMemberExtremes(out, deck, *run.model, *extremes.own, floor, "  ", units);
  }
  printCases(out, deck, run, a, extremes, units);
}

/// "reported: wstar = 0.00215712, theta_p = 0.00167015" (the deck's `report:`).
void printReported(std::ostream& out, const std::vector<std::pair<std::string, double>>& values) {
  const char* separator = "reported: ";
  for (const auto& [name, value] : values) {
    out << separator << name << " = " << formatValue(value);
    separator = ", ";
  }
  if (!values.empty()) out << "\n";
}

/// "section col: IPE300 (catalogue): A 53.81 cm^2, Iy 8356 cm^4, ..." in the tables' units
/// and axes (y-y strong, a member's local z).
void printCatalogSections(std::ostream& out, const std::vector<DeckCatalogSection>& sections) {
  for (const DeckCatalogSection& s : sections) {
    const CatalogProperties& p = s.properties;
    out << "section " << s.name << ": " << s.designation << " (catalogue; y-y strong = local z): A "
        << formatValue(p.A * 1e4) << " cm^2, Iy " << formatValue(p.Iy * 1e8) << " cm^4, Iz "
        << formatValue(p.Iz * 1e8) << " cm^4, It " << formatValue(p.It * 1e8) << " cm^4, Wel,y "
        << formatValue(p.Wely * 1e6) << " cm^3, Wel,z " << formatValue(p.Welz * 1e6)
        << " cm^3, Wpl,y " << formatValue(p.Wply * 1e6) << " cm^3, Wpl,z "
        << formatValue(p.Wplz * 1e6) << " cm^3";
    if (p.Iu > 0) out << ", Iu " << formatValue(p.Iu * 1e8) << " cm^4, Iv " << formatValue(p.Iv * 1e8) << " cm^4";
    out << "\n";
  }
}

/// A modal or torsion analysis' frequencies and what each mode does.
void printModes(std::ostream& out, const AnalysisOutcome& a, const ModalResult& m,
                const OutputUnits& units) {
  out << a.type << " analysis '" << a.name << "' (" << m.modes.size() << " modes)\n";
  for (std::size_t i = 0; i < m.modes.size(); ++i)
    out << "    mode " << padded(std::to_string(i + 1), 4)
        << padded(valueText(m.modes[i].frequencyHz, "Hz", units), 16) << m.modes[i].description
        << "\n";
}

const DeckCheck* findCheck(const Deck& deck, const std::string& name) {
  for (const DeckCheck& c : deck.checks)
    if (c.name == name) return &c;
  return nullptr;
}

std::string scientific(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", v);
  return buf;
}

}  // namespace

std::string padded(const std::string& s, std::size_t width) {
  return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' ');
}

std::string formatValue(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::abs(v) < 1e-300 ? 0.0 : v);
  return buf;
}

std::string valueText(double value, const std::string& unit, const OutputUnits& units,
                      const OutputUnits::Shown& own) {
  const OutputUnits::Shown shown = units.valueIn(unit, own);
  return shown.unit.empty() ? formatValue(value * shown.factor)
                            : formatValue(value * shown.factor) + " " + shown.unit;
}

std::string valueText(double value, const std::string& unit, const OutputUnits& units) {
  return valueText(value, unit, units, {1, unit});
}

void printRunResults(std::ostream& out, const Deck& deck, const RunResult& run,
                     const std::vector<AnalysisExtremes>* extremes, const OutputUnits& units) {
  const std::vector<AnalysisExtremes> computed =
      extremes ? std::vector<AnalysisExtremes>() : runExtremes(run);
  const std::vector<AnalysisExtremes>& x = extremes ? *extremes : computed;
  const SystemSize size = sizeOf(run);
  if (run.model->nodeCount() == 0)
    out << "model: none (the deck's analyses are mechanisms that need no model)\n";
  else
    out << "model: " << deck.dimension << ", " << size.nodes << " nodes, " << size.elements
        << " elements, " << size.dofs << " dofs (" << size.freeDofs << " free)\n";
  printReported(out, run.reported);
  printCatalogSections(out, run.catalogSections);
  for (const std::string& w : run.warnings) out << "warning: " << w << "\n";
  if (run.adequate) printAdequateChoice(out, *run.adequate);
  for (std::size_t i = 0; i < run.analyses.size(); ++i) {
    const AnalysisOutcome& a = run.analyses[i];
    std::visit(
        Overloaded{
            [&](const StaticOutcome&) { printStatic(out, deck, run, a, x.at(i), units); },
            [&](const SecondOrderResult&) {
              printStatic(out, deck, run, a, x.at(i), units);
              printSecondOrder(out, a);
            },
            [&](const BucklingResult&) { printBuckling(out, a); },
            [&](const ModalResult& r) { printModes(out, a, r, units); },
            [&](const TorsionOutcome& r) {
              printModes(out, a, r.modes, units);
              if (r.free)
                out << "    (no support holds the twist: mode 1 is the train turning as one)\n";
              if (!r.shafts.empty()) printTrain(out, r, units);
            },
            [&](const TransientOutcome&) { printTransient(out, a, units); },
            [&](const RotorResult auto& r) { printRotor(out, a, r, units); },
            [&](const CrankSliderOutcome&) { printCrankSlider(out, a, units); },
            [&](const MovingLoadOutcome& r) { printMovingLoad(out, a, r, units); },
            [&](const ResponseSpectrumResult& r) { printSpectrum(out, a, r, *run.model, units); },
            [&](const BaseMotionResult& r) { printBaseMotion(out, a, r, *run.model, units); }},
        a.result);
    for (const std::string& w : a.warnings) out << "warning: " << a.name << ": " << w << "\n";
  }
}

void printSweepResults(std::ostream& out, const Deck& deck, const SweepResult& sweep,
                       const OutputUnits& units) {
  if (sweep.runs.empty()) return;
  const RunResult& first = sweep.runs.front();
  const SystemSize size = sizeOf(first);
  out << "model: " << deck.dimension << ", " << size.nodes << " nodes, " << size.elements
      << " elements, " << size.dofs << " dofs (" << size.freeDofs << " free) at " << sweep.parameter
      << " = " << valueText(sweep.values.front(), sweep.unit, units) << "\n";
  out << "sweep over " << sweep.parameter << ": " << sweep.runs.size() << " values\n";
  for (const std::string& w : first.warnings) out << "warning: " << w << "\n";

  // Columns: the reactions of the first static analysis, the frequencies of the first modal.
  constexpr int kFrequencies = 3;
  constexpr std::size_t kColumn = 14;
  // The swept values in the user's unit of their quantity where set, else in their own.
  const OutputUnits::Shown swept = units.valueIn(sweep.unit, {1, sweep.unit});
  std::vector<std::string> headers{swept.unit.empty() ? sweep.parameter
                                                     : sweep.parameter + " " + swept.unit};
  for (const auto& [name, value] : first.reported) headers.push_back(name);
  auto staticOf = [](const RunResult& r) -> const StaticResult* {
    for (const auto& a : r.analyses)
      if (const StaticResult* s = staticsOf(a)) return s;
    return nullptr;
  };
  auto modalOf = [](const RunResult& r) -> const ModalResult* {
    for (const auto& a : r.analyses)
      if (const ModalResult* m = modesOf(a, *r.model).modes) return m;
    return nullptr;
  };
  if (const StaticResult* s = staticOf(first))
    for (const SupportReactions& support : reactionsBySupport(*s))
      for (const auto& [dof, value] : support.components)
        headers.push_back(support.support + " " + std::string(reactionName(dof)));
  int frequencies = 0;
  const OutputUnits::Shown hz = units.valueIn("Hz", {1, "Hz"});
  if (const ModalResult* m = modalOf(first)) {
    frequencies = std::min<int>(kFrequencies, int(m->modes.size()));
    for (int i = 0; i < frequencies; ++i) {
      // Built piece by piece: GCC 12 warns falsely (-Wrestrict) on the chained sum.
      std::string header = "f";
      header += std::to_string(i + 1);
      header += ' ';
      header += hz.unit;
      headers.push_back(header);
    }
  }
  const OutputUnits::Shown force = units.valueIn("N", {1, "N"});
  const OutputUnits::Shown moment = units.valueIn("N m", {1, "N m"});
  if (headers.size() == 1) return printTransientSweep(out, sweep, units);  // nothing static or modal
  out << "  ";
  for (const std::string& h : headers) out << padded(h, kColumn);
  out << "\n";
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < sweep.runs.size(); ++k) {
    const RunResult& run = sweep.runs[k];
    std::vector<double>& row = rows.emplace_back();
    row.push_back(sweep.values[k] * swept.factor);
    for (const auto& [name, value] : run.reported) row.push_back(value);
    if (const StaticResult* s = staticOf(run))
      for (const SupportReactions& support : reactionsBySupport(*s))
        for (const auto& [dof, value] : support.components)
          row.push_back(value * (isRotation(dof) ? moment : force).factor);
    if (const ModalResult* m = modalOf(run))
      for (int i = 0; i < frequencies && i < int(m->modes.size()); ++i)
        row.push_back(m->modes[i].frequencyHz * hz.factor);
  }
  // Each column is one quantity: a value below its largest's round-off is shown as 0 (a
  // reported 1 - cos(2 pi) as 0, not 1e-33; NoiseFloor.hpp's rule).
  std::vector<double> largest(headers.size(), 0.0);
  for (const std::vector<double>& row : rows)
    for (std::size_t c = 0; c < row.size() && c < largest.size(); ++c)
      largest[c] = std::max(largest[c], std::abs(row[c]));
  for (const std::vector<double>& row : rows) {
    out << "  ";
    for (std::size_t c = 0; c < row.size(); ++c)
      out << padded(formatValue(c < largest.size()
                                    ? zeroAtOrBelow(row[c], kNegligibleShare * largest[c])
                                    : row[c]),
                    kColumn);
    out << "\n";
  }
  out << "  (reactions in " << force.unit << " and " << moment.unit << " on the structure)\n";
  printTransientSweep(out, sweep, units);

  printSweepStressPeaks(out, deck, sweep, units);
}

int printChecks(std::ostream& out, const Deck& deck, const std::vector<const RunResult*>& runs,
                const std::vector<std::string>& labels, const OutputUnits& units) {
  int failed = 0, passed = 0, skipped = 0;
  std::size_t nameWidth = 10, quantityWidth = 10;
  for (const DeckCheck& c : deck.checks) {
    nameWidth = std::max(nameWidth, c.name.size() + 2);
    quantityWidth = std::max(quantityWidth, c.quantity.text.size() + 2);
  }
  out << "checks:\n";
  if (deck.checks.empty()) out << "  (the deck has no checks)\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string prefix = labels.empty() || labels[i].empty() ? "" : padded(labels[i], 14);
    for (const Check& c : runs[i]->checks) {
      const bool ok = c.pass();
      (ok ? passed : failed)++;
      // The values in the user's unit of the quantity where set, else in the check's own;
      // against a zero reference the error and the tolerance are absolute, in that unit.
      const ShownCheck shown = shownCheck(c, units);
      const std::string unit = shown.unit.empty() ? "" : " " + shown.unit;
      const auto value = [&](double v) { return formatValue(v) + unit; };
      const bool absolute = shown.absolute;
      out << "  " << (ok ? "PASS  " : "FAIL  ") << prefix << padded(c.name, nameWidth)
          << padded(c.quantity, quantityWidth) << padded(value(shown.computed), 18) << "ref "
          << padded(value(shown.reference), 18) << (absolute ? "abs.err " : "rel.err ")
          << padded(scientific(shown.error) + (absolute ? unit : ""), 10) << "tol "
          << scientific(shown.tolerance) << (absolute ? unit : "") << "\n";
      if (shown.paper)
        out << "        " << prefix << "paper prints " << value(*shown.paper) << " ("
            << scientific(std::abs(c.computed - *c.paper) / std::abs(*c.paper))
            << " from the computed value): " << c.reason << "\n";
    }
    if (runs.size() == 1)
      for (const std::string& name : runs[i]->skippedChecks) {
        ++skipped;
        const DeckCheck* d = findCheck(deck, name);
        out << "  n/a   " << prefix << padded(name, nameWidth)
            << (d ? "(when: " + d->condition + " is false here)" : "") << "\n";
      }
  }
  // Over several runs (a sweep) one line per check that did not apply everywhere.
  if (runs.size() > 1)
    for (const DeckCheck& c : deck.checks) {
      int count = 0;
      for (const RunResult* run : runs)
        count += int(std::count(run->skippedChecks.begin(), run->skippedChecks.end(), c.name));
      if (count == 0) continue;
      skipped += count;
      out << "  n/a   " << padded(c.name, nameWidth) << "at " << count << " of " << runs.size()
          << " values (when: " << c.condition << " is false there)\n";
    }
  out << "  " << passed << " passed, " << failed << " failed, " << skipped << " not applicable\n";
  return failed;
}

}  // namespace beamrotor::cli
