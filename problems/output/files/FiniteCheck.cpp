// Refusal of NaN and infinity in a run (see FiniteCheck.hpp), with messages naming the value.
#include "problems/output/files/FiniteCheck.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

namespace {

void require(double x, const std::string& what) {
  if (!std::isfinite(x)) throw std::runtime_error(what + " is " + exactDecimal(x));
}

void requireField(const Model& model, const NodalField& field, const std::string& what) {
  // The message only for a value that fails: describing every dof would cost more than the
  // rest of the writing (10^5 nodes).
  for (int n = 0; n < field.rows(); ++n)
    for (Dof d : kAllDofs)
      if (!std::isfinite(field(n, dofIndex(d))))
        require(field(n, dofIndex(d)), what + " at " + model.describe({n, d}));
}

void requireTimes(const SolveTimings& t, const std::string& where) {
  require(t.assembly, where + ": assembly time");
  require(t.factor, where + ": factorisation time");
  require(t.solve, where + ": solve time");
  require(t.total, where + ": total time");
}

void requireStatic(const Model& model, const StaticResult& r, const std::string& where) {
  requireField(model, r.displacement, where + ": displacement");
  for (const ReactionComponent& c : r.reactions)
    require(c.value, where + ": reaction of support '" + c.support + "' along " +
                         std::string(dofName(c.dof)));
  for (const ContactState& c : r.contacts) {
    const std::string at = where + ": contact '" + c.name + "' ";
    require(c.value, at + "value");
    require(c.bound, at + "bound");
    require(c.gap, at + "gap");
    require(c.force, at + "force");
  }
  require(r.rcond, where + ": rcond");
  requireTimes(r.time, where);
}

void requireModal(const Model& model, const ModalResult& r, const std::string& where) {
  require(r.shift, where + ": shift");
  for (int k = 0; k < 3; ++k)
    require(r.totalMass[k], where + ": total mass along " + std::string(dofName(kAllDofs[k])));
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    const Mode& mode = r.modes[m];
    const std::string at = where + ": mode " + std::to_string(m + 1);
    require(mode.eigenvalue, at + " eigenvalue");
    require(mode.frequencyHz, at + " frequency");
    requireField(model, mode.shape, at + " shape");
    for (int k = 0; k < 3; ++k)
      require(mode.effectiveMass[k],
              at + " effective mass along " + std::string(dofName(kAllDofs[k])));
    for (Dof d : kAllDofs)
      require(mode.energyShare[dofIndex(d)], at + " energy share of " + std::string(dofName(d)));
  }
  requireTimes(r.time, where);
}

}  // namespace

void requireFinite(const RunResult& run) {
  if (!run.model) throw std::invalid_argument("run of '" + run.deckName + "' has no model");
  const Model& model = *run.model;
  for (const auto& [name, value] : run.parameters) require(value, "parameter '" + name + "'");
  require(run.seconds, "run time");
  for (const Check& c : run.checks) {
    require(c.computed, "check '" + c.name + "': computed value");
    require(c.reference, "check '" + c.name + "': reference value");
    require(c.tolerance, "check '" + c.name + "': tolerance");
  }
  for (int n = 0; n < model.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(model.nodes()[n][k]))
        require(model.nodes()[n][k],
                "coordinate " + std::to_string(k) + " of node " + std::to_string(n));
  for (const AnalysisOutcome& a : run.analyses) {
    const std::string where = "analysis '" + a.name + "' (" + a.type + ")";
    if (const StaticResult* s = staticsOf(a)) requireStatic(model, *s, where);
    for (const CaseOutcome& c : casesOf(a))
      requireStatic(model, c.statics, where + ", " + (c.combination ? "combination '" : "case '") +
                                          c.name + "'");
    if (const ModesOn m = modesOf(a, model); m.modes) requireModal(*m.model, *m.modes, where);
  }
}

}  // namespace beamrotor
