#include "problems/deck/Quantity.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "fem/Recovery.hpp"

namespace beamrotor {

namespace {

constexpr const char* kGrammar =
    "expected 'reaction SUPPORT DOF', 'displacement POINT DOF', 'frequency N', 'stress max', "
    "'shear max' or 'moment max'";

/// Stations per element for the maxima: resultants vary at most quadratically along an
/// element (uniform distributed load), so 8 intervals place a station within L/16 of any
/// interior extremum, and the quadratic is flat there to (1/16)^2 relative.
constexpr int kStationsPerElement = 8;

/// ux..rz, or the force/moment names fx fy fz mx my mz for the same dofs.
Dof parseComponent(const std::string& word) {
  if (auto d = parseDof(word)) return *d;
  static const std::vector<std::pair<std::string, Dof>> aliases{
      {"fx", Dof::ux}, {"fy", Dof::uy}, {"fz", Dof::uz},
      {"mx", Dof::rx}, {"my", Dof::ry}, {"mz", Dof::rz}};
  for (const auto& [name, dof] : aliases)
    if (word == name) return dof;
  throw std::invalid_argument("'" + word +
                              "' is not a component (ux uy uz rx ry rz, or fx fy fz mx my mz)");
}

}  // namespace

Quantity parseQuantity(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  Quantity q;
  q.text = text;
  if (words.empty()) throw std::invalid_argument(std::string("empty quantity; ") + kGrammar);
  const std::string& head = words[0];
  if ((head == "reaction" || head == "displacement") && words.size() == 3) {
    q.kind = head == "reaction" ? Quantity::Kind::reaction : Quantity::Kind::displacement;
    q.target = words[1];
    q.dof = parseComponent(words[2]);
    return q;
  }
  if (head == "frequency" && words.size() == 2) {
    q.kind = Quantity::Kind::frequency;
    const std::string& n = words[1];
    const bool digits = !n.empty() && n.size() <= 4 &&
                        std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || std::stoi(n) < 1)
      throw std::invalid_argument("mode number '" + n + "' must be a whole number from 1");
    q.mode = std::stoi(n);
    return q;
  }
  if ((head == "stress" || head == "shear" || head == "moment") && words.size() == 2 &&
      words[1] == "max") {
    q.kind = head == "stress"  ? Quantity::Kind::maxStress
             : head == "shear" ? Quantity::Kind::maxShear
                               : Quantity::Kind::maxMoment;
    return q;
  }
  throw std::invalid_argument("cannot read '" + text + "'; " + kGrammar);
}

double measure(const Quantity& q, const AnalysisOutcome& outcome, const Model& model) {
  if (q.kind == Quantity::Kind::frequency) {
    if (!outcome.modal) throw std::invalid_argument("analysis '" + outcome.name + "' is not modal");
    const auto& modes = outcome.modal->modes;
    if (q.mode > int(modes.size()))
      throw std::invalid_argument("analysis '" + outcome.name + "' found only " +
                                  std::to_string(modes.size()) + " modes");
    return modes[q.mode - 1].frequencyHz;
  }
  if (!outcome.statics)
    throw std::invalid_argument("analysis '" + outcome.name + "' is not static");
  const StaticResult& r = *outcome.statics;
  switch (q.kind) {
    case Quantity::Kind::reaction:
      return r.reaction(q.target, q.dof);
    case Quantity::Kind::displacement:
      return r.displacement(model.node(q.target), dofIndex(q.dof));
    default: {
      double largest = 0;
      for (const BeamStation& s : recoverBeamFields(model, r.displacement, kStationsPerElement)) {
        const double v = q.kind == Quantity::Kind::maxStress ? s.stress
                         : q.kind == Quantity::Kind::maxShear
                             ? s.shear
                             : std::hypot(s.forces.My, s.forces.Mz);
        largest = std::max(largest, v);
      }
      return largest;
    }
  }
}

}  // namespace beamrotor
