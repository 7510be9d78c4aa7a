// The exact extrema along a model's members (Model::members, chains of line elements): the
// largest and smallest value of each stress resultant (SectionForceSeries are polynomials in
// the position, so the extremes lie at an element end or where a derivative vanishes), the
// largest deflection of a member from its chord, and the largest displacement of the whole
// structure, inside elements as well as at nodes. Displacements along an element are
// polynomials of degree at most 5 (cubic shape functions plus a linear span load's quintic),
// recovered exactly from six values, so these too are found from polynomials, not samples.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The six stress resultants, in the order of SectionForces.
enum class ForceComponent { N, Vy, Vz, T, My, Mz };
inline constexpr std::array<ForceComponent, 6> kForceComponents{
    ForceComponent::N,  ForceComponent::Vy, ForceComponent::Vz,
    ForceComponent::T, ForceComponent::My, ForceComponent::Mz};
/// "N", "Vy", "Vz", "T", "My", "Mz".
const char* componentName(ForceComponent c);
/// Whether c is a moment (T, My, Mz: N m) rather than a force (N, Vy, Vz: N).
constexpr bool isMomentComponent(ForceComponent c) {
  return c == ForceComponent::T || c == ForceComponent::My || c == ForceComponent::Mz;
}
/// The component of f.
double componentOf(const SectionForces& f, ForceComponent c);

/// One resultant of a series as a polynomial in s (exact: the series is).
Polynomial componentPolynomial(const SectionForceSeries& series, ForceComponent c);

/// A value at a place on a member.
struct MemberValue {
  int element = -1;   ///< index into model.elements()
  double s = 0;       ///< fraction of that element's length
  double along = 0;   ///< distance from the member's start (m)
  double value = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< the place, undeformed (m, global)
};

/// The undeformed place (m, global) at fraction s of line element `element`.
Eigen::Vector3d placeOnElement(const Model& model, int element, double s);

/// Where fraction s of element `element` lies on the model's members: the member's index
/// into Model::members() and the distance from its start (m); nullopt when no member holds it.
std::optional<std::pair<int, double>> memberLocation(const Model& model, int element, double s);

/// The largest and smallest value of one resultant along a member.
struct ComponentRange {
  MemberValue max, min;
};

/// A member resultant's largest and smallest value, without their places.
struct RangeValues {
  double max = 0, min = 0;
};

/// Resultant ranges of member `elements` (line elements from its start to its end) in a
/// static solution, in the order of kForceComponents.
std::array<ComponentRange, 6> memberForceRanges(const LoadedSolution& solution,
                                                const std::vector<int>& elements);

/// The largest distance (m) of the member's deflected axis from its deflected chord (the line
/// through its displaced ends), measured across the chord's original direction.
MemberValue largestChordDeflection(const LoadedSolution& solution,
                                   const std::vector<int>& elements);

/// The largest translation magnitude (m) anywhere: inside every line element (static
/// solution with its span loads) and at every node. element is -1 for a node off the beams
/// (then `along` is unused and s is the node index).
MemberValue largestDisplacement(const LoadedSolution& solution);

}  // namespace beamrotor
