// A deck after reading: every expression evaluated for one set of parameter values, every
// name checked, every number in range. Plain values; ModelBuilder turns it into a Model and
// DeckRunner solves it. Each item keeps its place in the file for later messages.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "elements/Beam.hpp"
#include "fem/model/Dof.hpp"
#include "fem/model/Section.hpp"
#include "meshes/TrainBuilder.hpp"
#include "problems/deck/AnalysisKinds.hpp"
#include "problems/deck/catalog/SectionCatalog.hpp"
#include "problems/deck/study/DeckAccuracy.hpp"
#include "problems/deck/crank/DeckCrank.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/structure/DeckFrame.hpp"
#include "problems/deck/rotor/DeckRotor.hpp"
#include "problems/deck/transient/DeckTransient.hpp"
#include "problems/deck/OutputChoices.hpp"
#include "problems/deck/Quantity.hpp"
#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

/// A prismatic piece of the line (see meshes/LineBuilder Segment).
struct DeckSegment {
  std::string name;   ///< optional; loads refer to segments by name
  double length = 0;  ///< m
  std::shared_ptr<const Section> section;
  std::string sectionName;
  int elements = 0;  ///< element count, or 0 to use size
  double size = 0;   ///< largest element length (m) when elements == 0
  /// A lateral rotor's shaft: the axial force it carries (N, tension positive), given because
  /// lateral models have no axial dof to carry it; it enters through the geometric stiffness.
  double axialForce = 0;
  BeamOptions options;
  DeckPlace place;
  /// Elements the line builder will make, at most (points add a cut each).
  double elementEstimate() const { return elements > 0 ? elements : std::ceil(length / size); }
};

/// The values a `general` section leaves out (true: missing), with its place: a run that
/// needs one (stresses, 3D torsion, a Timoshenko element) is refused there, never given a
/// default (problems/deck/SectionNeeds).
struct DeckSectionGaps {
  std::string name;
  std::string path;  ///< its field path, e.g. "sections[2]"
  DeckPlace place;   ///< the section's map
  bool depth = false, width = false, J = false, kappa = false;
};

/// A named station on the line, `at` metres from its start.
struct DeckPoint {
  std::string name;
  double at = 0;
  DeckPlace place;
};

/// A support at a point: fixed dofs (value 0) and prescribed values (m, rad).
struct DeckSupport {
  std::string name;
  std::string point;
  std::vector<std::pair<Dof, double>> dofs;  ///< in the deck's order, fixed ones first
  DeckPlace place;
};

/// A linear spring (and damper) on one dof, grounded or between two points.
struct DeckSpring {
  std::string name;
  std::string point;
  std::string toPoint;  ///< empty: grounded
  Dof dof = Dof::uy;
  double k = 0;  ///< N/m or N m/rad
  double c = 0;  ///< N s/m or N m s/rad
  DeckPlace place;
};

/// A one-dof stop against the fixed frame (fem ContactConstraint): the dof stays within
/// [lower, upper]; a missing bound is infinite.
struct DeckContact {
  std::string name;
  std::string point;
  Dof dof = Dof::uy;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  DeckPlace place;
};

/// A rigid tie between two points (`rigid_links:`, or one member of a `diaphragms:` entry):
/// the slave's dofs follow the master as one rigid body (fem RigidTie).
struct DeckRigidLink {
  std::string name;
  std::string master, slave;  ///< point names
  std::vector<Dof> dofs;      ///< the slave's dofs that follow
  DeckPlace place;
};

/// A rigid body lumped at a point (elements/PointInertia); its axis is the line's.
struct DeckMass {
  std::string name;
  std::string point;
  double m = 0, Jp = 0, Jd = 0;  ///< kg, kg m^2
  DeckPlace place;
};

/// End releases of every beam meeting at a point.
struct DeckHinge {
  std::string point;
  std::vector<Dof> released;  ///< rotations
  DeckPlace place;
};

/// A point force/moment, a distributed load on segments, self-weight, or a temperature change.
struct DeckLoad {
  enum class Kind { point, distributed, selfWeight, temperature };
  Kind kind = Kind::point;
  std::string point;                               ///< point loads
  std::vector<std::pair<Dof, double>> components;  ///< point loads: N on ux.., N m on rx..
  Eigen::Vector3d q = Eigen::Vector3d::Zero();     ///< distributed: N/m, global frame, at `from`
  Eigen::Vector3d qEnd = Eigen::Vector3d::Zero();  ///< distributed: at `to`; linear between
  double from = 0, to = 1;    ///< distributed: the loaded part of each segment or member
                              ///< (fractions of its length from its start)
  bool inMemberAxes = false;  ///< distributed: q is in each member's local axes instead
  /// distributed, global axes: each component acts per length of the member's projection
  /// across that component's direction (a roof load per plan length), not per member length.
  bool perProjectedLength = false;
  double g = 9.81;                                 ///< self-weight: m/s^2, acting along -y
  /// temperature: the change at the centroid and its rise through the depth towards local +y
  /// and +z, from the lowest to the highest fibre (K; thermalStrain, LineElement.hpp)
  double dT = 0, dTy = 0, dTz = 0;
  std::vector<int> segments;  ///< distributed and self-weight: indices; all if empty
  DeckPlace place;
};

/// A named load case (`load_cases:`): loads in the syntax of `loads:`, solved on its own by
/// each static analysis.
struct DeckLoadCase {
  std::string name;
  std::vector<DeckLoad> loads;
  DeckPlace place;
};

/// A named combination (`combinations:`): the factored sum of load cases.
struct DeckCombination {
  std::string name;
  std::vector<std::pair<std::string, double>> factors;  ///< case name, factor; deck order
  DeckPlace place;
};

/// A load scaled by a factor (point components, q, g for self-weight, or the temperatures).
inline DeckLoad scaledLoad(DeckLoad l, double factor) {
  for (auto& [d, value] : l.components) value *= factor;
  l.q *= factor;
  l.qEnd *= factor;
  l.g *= factor;
  l.dT *= factor;
  l.dTy *= factor;
  l.dTz *= factor;
  return l;
}

/// One analysis to run.
struct DeckAnalysis {
  AnalysisSpec kind;  ///< its row in the table of analysis kinds, with the settings it gives
  std::string name;   ///< defaults to the type
  DeckPlace place;
  /// The deck's `type:` for it, e.g. "campbell" (for messages; ask `kind` what it is).
  std::string type() const { return analysisTypeName(kind); }
  /// Its row's settings when it is a `Spec`, else null.
  template <class Spec>
  const Spec* as() const {
    return std::get_if<Spec>(&kind);
  }
  template <class Spec>
  Spec* as() {
    return std::get_if<Spec>(&kind);
  }
};

/// A closed-form comparison.
struct DeckCheck {
  std::string name;
  Quantity quantity;
  std::string analysis;  ///< the analysis it reads (resolved: never empty)
  std::string loadCase;  ///< `case:`: a load case or combination of a static analysis; or empty
  double reference = 0;
  double tolerance = 0;    ///< on the relative error
  bool applicable = true;  ///< false when its `when:` condition is false
  std::string condition;   ///< the `when:` text, empty if none
  std::optional<double> paper;  ///< `paper:` the printed figure when the reference differs
  std::string reason;           ///< `reason:` why the reference differs from `paper:`
  DeckPlace place;
};

/// The parameter a sweep varies and the values it takes.
struct DeckSweep {
  std::string parameter;
  std::vector<double> values;
  DeckPlace place;
};

/// A section the deck picked from the catalogue (`catalog: IPE300`), with the properties the
/// steel tables print, in their axes (y-y strong; see SectionCatalog.hpp), for the output.
struct DeckCatalogSection {
  std::string name;         ///< the deck's section name
  std::string designation;  ///< as the table spells it
  CatalogProperties properties;
};

struct Deck {
  std::string path;   ///< as given, for messages
  std::string stem;   ///< e.g. "pump_rod"
  std::string title;  ///< one line describing the scene (may be empty)
  std::vector<std::pair<std::string, double>> parameters;  ///< after overrides, deck order
  std::vector<std::pair<std::string, double>> derived;     ///< named values computed from them
  std::vector<std::pair<std::string, double>> reported;    ///< `report:` names with their values
  /// The dimensions of the parameters and derived values written with a unit (values in SI).
  std::vector<std::pair<std::string, Dimension>> dimensions;
  /// The dimensions the parameters written without a unit take from the fields they flow
  /// into (BareParameters.hpp): a command-line value with a unit must have it.
  /// A field reading bare numbers in another unit (rpm) gives that unit's size as well.
  std::vector<std::pair<std::string, FieldUnit>> bareDimensions;
  /// "file:line:col: field: message" lines for implausible values (MaterialPlausibility.hpp).
  std::vector<std::string> warnings;

  std::string dimension = "planar";  ///< "planar", "3d" or "lateral"
  DofSet dofs = DofSet::planar();
  BeamOptions beam;  ///< the default element formulation

  std::vector<DeckSegment> segments;  ///< the line's pieces, or a frame's members
  std::optional<DeckFrame> frame;     ///< `nodes:` and `members:` (segments are its members)
  std::vector<DeckSectionGaps> sectionGaps;  ///< one per `general` section missing something
  std::vector<DeckCatalogSection> catalogSections;  ///< the sections taken from the catalogue
  std::vector<DeckPoint> points;  ///< including the automatic "start" and "end"
  std::vector<DeckSupport> supports;
  std::vector<DeckSpring> springs;
  std::vector<DeckContact> contacts;
  std::vector<DeckRigidLink> rigidLinks;  ///< `rigid_links:` and the diaphragms' ties
  std::vector<DeckMass> masses;
  std::vector<DeckHinge> hinges;
  std::vector<DeckLoad> loads;
  std::vector<DeckLoadCase> loadCases;        ///< `load_cases:`, deck order
  std::vector<DeckCombination> combinations;  ///< `combinations:`, deck order
  DeckRotorModel rotor;  ///< bearings and proportional damping
  TrainSpec train;       ///< `train:` shafts, disks, couplings and gears in torsion (or none)
  std::vector<DeckAnalysis> analyses;
  std::vector<DeckCheck> checks;
  std::optional<DeckSweep> sweep;
  std::optional<DeckAccuracy> accuracy;  ///< `accuracy:`: pick the cheapest adequate model
  DeckOutput output;                     ///< `output:`: chart format, a sweep's files per value

  /// Total length of the line (m).
  double length() const {
    double L = 0;
    for (const auto& s : segments) L += s.length;
    return L;
  }
};

/// The name spring `index` (its place in `springs:`, from 0) goes by in outputs and check
/// quantities: its own, or `spring<N>` (N its place, from 1) when it has none.
inline std::string springName(const Deck& deck, std::size_t index) {
  if (!deck.springs.at(index).name.empty()) return deck.springs[index].name;
  std::string name = "spring";  // appended: GCC 12 warns on "literal" + a temporary string
  name += std::to_string(index + 1);
  return name;
}

}  // namespace beamrotor
