// The table of analysis kinds: one row per `type:` an entry of `analyses:` may have. A row is
// a spec type declared in its family's room (structure/, transient/, crank/, rotor/) that
// states its deck type, its reader and the check quantities it answers, and holds the settings
// its deck entry gives; the table is the list of those types, and the only place that compares
// a deck's type string. Adding a kind is one
// alternative here plus its own files.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "problems/deck/Quantity.hpp"
#include "problems/deck/crank/CrankKind.hpp"
#include "problems/deck/rotor/RotorKinds.hpp"
#include "problems/deck/structure/StructureKinds.hpp"
#include "problems/deck/torsion/TorsionKind.hpp"
#include "problems/deck/transient/TransientKind.hpp"

namespace beamrotor {

/// The rows, in the order messages list them. A quantity several rows answer is read by
/// default from the first (a frequency from a modal analysis before a rotor one).
using AnalysisSpec = std::variant<StaticSpec, ModalSpec, BucklingSpec, TransientSpec, RotorSpec,
                                  CampbellSpec, UnbalanceSpec, RigidBodySpec, FrequencyResponseSpec,
                                  CrankSliderSpec, CriticalSpeedMapSpec, BearingLoadsSpec,
                                  TorsionSpec, LevelOneSpec, MovingLoadSpec, RunUpSpec,
                                  ResponseSpectrumSpec, BaseMotionSpec>;

/// Every row's deck type, in row order.
std::vector<std::string> analysisTypeNames();
/// The row whose deck type is `type`; none when no row has it.
std::optional<AnalysisSpec> analysisSpecNamed(std::string_view type);
/// A row's deck type, e.g. "campbell".
std::string analysisTypeName(const AnalysisSpec& spec);
template <class Spec>
std::string analysisTypeName() {
  return std::string(Spec::deckType);
}

/// Whether row Spec answers quantity q.
template <class Spec>
bool answers(const Quantity& q) {
  for (Quantity::Kind k : Spec::answers)
    if (k == q.kind) return true;
  return false;
}
/// Whether the row `spec` answers quantity q.
bool answers(const AnalysisSpec& spec, const Quantity& q);
/// The deck type of the first row that answers q: what a check naming no analysis reads.
std::string defaultAnalysisType(const Quantity& q);

/// Whether the row belongs to the rotor family (RotorKinds.hpp).
bool isRotorAnalysis(const AnalysisSpec& spec);
/// The rotor family's settings of a rotor row; null for any other row.
const RotorFamily* rotorSettings(const AnalysisSpec& spec);
RotorFamily* rotorSettings(AnalysisSpec& spec);
/// How many modes (or buckling factors) the row computes; 0 for a row that computes none.
int modesComputed(const AnalysisSpec& spec);

}  // namespace beamrotor
