// Internal to the deck reader: the state shared by the functions that read each part of a
// deck (DeckReader.cpp, ReadLine.cpp, ReadAttachments.cpp, ReadStudy.cpp), and the lookups
// that turn names in the deck into checked references.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/parse/NumericReads.hpp"
#include "problems/deck/NameIndex.hpp"
#include "problems/deck/study/Overrides.hpp"

namespace beamrotor::reader {

struct Context {
  Field root;
  Deck& deck;
  ExpressionEvaluator evaluator;
  std::vector<Material> materials;  ///< in deck order
  std::vector<std::shared_ptr<const Section>> sections;
  /// The expression of each parameter and derived value without a unit, as written, and the
  /// command-line values with a unit for such parameters: both wait for the fields to tell
  /// those parameters' dimensions (BareParameters.hpp).
  std::vector<std::pair<std::string, std::string>> bareTexts;
  std::vector<ParameterOverride> unitOverridesOfBare;
  /// The fields giving values of such a parameter elsewhere in the deck (a sweep's), with the
  /// parameter's name: read in SI as written, their units checked once its dimension is known.
  std::vector<std::pair<std::string, Field>> valuesOfBare;
  /// deck.points, deck.segments and a frame's joints by name (so that reading stays linear in
  /// the model's size): read through pointNamed, segmentNamed and jointNamed.
  NameIndex pointsByName, segmentsByName, jointsByName;

  /// The index in deck.points, deck.segments or the frame's joints of the one named `name`.
  std::optional<int> pointNamed(const std::string& name) const;
  std::optional<int> segmentNamed(const std::string& name) const;
  std::optional<int> jointNamed(const std::string& name) const;
  /// The point a field names; fails with a did-you-mean suggestion.
  const DeckPoint& point(const Field& f) const;
  /// The index of the segment a field names.
  int segment(const Field& f) const;
  /// A dof name (ux .. rz) the model carries.
  Dof dof(const Field& f) const;
  /// A rotation dof the model carries.
  Dof rotation(const Field& f) const;
  /// The dofs the model carries, for messages: "ux, uy, rz".
  std::string carriedNames() const;
};

/// Materials (E, nu or G, rho) into c.materials.
/// Analyses other than first-order statics refused in a deck with rigid links or diaphragms.
void refuseTiedAnalyses(const Context& c);
void readMaterials(Context& c);
/// Cross-sections into c.sections.
void readSections(Context& c);
/// Segments and points (plus the automatic "start" and "end"), or a frame (readFrame).
void readLine(Context& c);
/// A segment's section, element count or size and formulation into s (length aside).
void readSegmentMesh(const Context& c, const Field& f, DeckSegment& s);
/// A frame: `nodes:`, `members:` (one segment each) and `points:` along members, plus the
/// places `{member: NAME, at: FRACTION}` that attachments name (ReadFrame.cpp).
void readFrame(Context& c);
/// The point a `{member: NAME, at: FRACTION}` (or `at_length: METRES`) map names; readFrame
/// made it.
const DeckPoint& memberPoint(const Context& c, const Field& f);
/// "OWNER@FRACTION" with every digit the fraction has: the name of a place inside a member or
/// segment (two places never share a name).
std::string fractionPlaceName(const std::string& owner, double fraction);
/// A mesh node at `fraction` (0 to 1) of member `member`, where a partial load starts or
/// ends; nothing at its ends, which are joints already.
void addMemberStation(Context& c, int member, double fraction, const DeckPlace& place);
/// Supports, springs, contacts, masses, hinges and loads.
void readAttachments(Context& c);
/// A mass given as a disk's geometry {D, bore, width, rho}: its m, Jp, Jd into `mass`.
void readDisk(const Context& c, const Field& disk, DeckMass& mass);
/// A drive train in torsion (`train:`) into c.deck.train (ReadTrain.cpp).
void readTrain(Context& c);
/// The train station a field names ("SHAFT.STATION"); fails with a did-you-mean suggestion.
TrainStation trainStation(const Context& c, const Field& f);
/// Bearings and proportional damping (ReadRotor.cpp).
void readRotorModel(Context& c);
/// Fails at a modal analysis when a bearing is cross-coupled at rest (non-symmetric K).
void requireSymmetricAtRest(const Context& c, const Field& analysis);
/// Fails at `f` unless the names a rotor quantity refers to exist in analysis `a`.
void resolveRotorQuantity(const Context& c, const Quantity& q, const Field& f,
                          const DeckAnalysis& a);
/// Adds the speed an unbalance_amplitude check reads to its analysis's speeds.
void addCheckedSpeed(Context& c, const DeckCheck& k);
/// The row of the table of analysis kinds that an analysis' `type:` names; fails listing the
/// known types (AnalysisKinds.cpp).
AnalysisSpec analysisKind(const Field& type);
/// The fields of analysis entry `f` into a, by the reader of its row a.kind; then, when the
/// row needs mass, requireMass.
void readAnalysisKind(const Context& c, const Field& f, DeckAnalysis& a);
/// Fails at analysis entry `f` (of deck type `type`) when the deck has no inertia: no density
/// and no lumped mass.
void requireMass(const Context& c, const Field& f, const std::string& type);
/// Whether an analysis entry is one that needs no model: its row says so (a crank-slider, or
/// a rigid-body analysis given its `body:`).
bool isMechanismAnalysis(const Field& analysis);
/// True when the deck has no segments, points or frame and only such analyses: it needs no
/// model at all.
bool modelFree(const Context& c);
/// The mechanism a crank-slider analysis `f` gives.
DeckCrankSlider readCrankSlider(const Context& c, const Field& f);
/// A rigid-body analysis' `body:` (weight or mass, radius of gyration, l1, l2, C1, C2).
void readTwoDofBody(const Context& c, const Field& f, DeckRotorAnalysis& r);
/// Fails at `f` when a crank quantity asks for what analysis `a` was not given (masses, a
/// plunger, a lambda outside its table).
void resolveCrankQuantity(const Quantity& q, const Field& f, const DeckAnalysis& a);
/// Fails at `f` unless a torsion quantity names a joint, shaft or station of the train and
/// analysis `a` has harmonic torques at an operating speed (ReadTorsion.cpp).
void resolveTorsionQuantity(const Context& c, const Quantity& q, const Field& f,
                            const DeckAnalysis& a);
/// Fails at `f` unless `reaction NAME DOF` names a support that holds DOF, or a spring, bearing
/// or contact that acts along it (each exerts a force on the structure, reported by its name).
void requireReactionTarget(const Deck& deck, const Quantity& q, const Field& f);
/// Fails at `f` unless the quantity's names exist in the deck and its analysis (the one
/// `analysisField` names, else the first that can give it) can give it; returns the name of
/// the analysis it reads. `applicable`: whether a check's `when:` holds (history times).
std::string resolveQuantity(const Context& c, Quantity& q, const Field& f,
                            const std::optional<Field>& analysisField, bool applicable);
/// Fails when a parameter without a unit flows into fields of two dimensions, or a
/// command-line value with a unit does not fit the dimension its fields give it; records the
/// dimensions found in deck.bareDimensions. `reads`: the numbers the reading read.
void checkBareParameters(Context& c, const std::vector<NumericRead>& reads);
/// Analyses, checks and the sweep.
void readStudy(Context& c, const std::vector<ParameterOverride>& overrides);

/// The settings of a transient analysis `f` (a map with type: transient).
DeckTransient readTransient(const Context& c, const Field& f);
/// Checks a history quantity against transient analysis `analysis` and evaluates its time
/// (which must lie within the run when the check applies).
void resolveHistoryQuantity(const Context& c, Quantity& q, const Field& f,
                            const DeckAnalysis& analysis, bool applicable);
/// `report:`: names of parameters and derived values into deck.reported.
void readReport(Context& c);
/// `accuracy:` (ReadAccuracy.cpp).
void readAccuracy(Context& c);
/// `output:`: chart format and a sweep's per-value files into deck.output (ReadOutput.cpp).
void readOutput(Context& c);

/// The beam formulation a field names (euler-bernoulli, timoshenko, ...).
BeamTheory formulationOf(const Field& f);

/// Fails at `f` when `name` is already in `taken`; otherwise records it.
void claimName(const Field& f, const std::string& name, TakenNames& taken,
               const std::string& what);

}  // namespace beamrotor::reader
