// Internal to the deck reader: the state shared by the functions that read each part of a
// deck (DeckReader.cpp, ReadLine.cpp, ReadAttachments.cpp, ReadStudy.cpp), and the lookups
// that turn names in the deck into checked references.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/Expression.hpp"
#include "problems/deck/Field.hpp"
#include "problems/deck/Overrides.hpp"

namespace beamrotor::reader {

struct Context {
  Field root;
  Deck& deck;
  ExpressionEvaluator evaluator;
  std::vector<Material> materials;  ///< in deck order
  std::vector<std::shared_ptr<const Section>> sections;

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
void readMaterials(Context& c);
/// Cross-sections into c.sections.
void readSections(Context& c);
/// Segments and points (plus the automatic "start" and "end").
void readLine(Context& c);
/// Supports, springs, contacts, masses, hinges and loads.
void readAttachments(Context& c);
/// Analyses, checks and the sweep.
void readStudy(Context& c, const std::vector<ParameterOverride>& overrides);

/// `report:`: names of parameters and derived values into deck.reported.
void readReport(Context& c);

/// The beam formulation a field names (euler-bernoulli, timoshenko, ...).
BeamTheory formulationOf(const Field& f);

/// Fails at `f` when `name` is already in `taken`; otherwise records it.
void claimName(const Field& f, const std::string& name, std::vector<std::string>& taken,
               const std::string& what);

}  // namespace beamrotor::reader
