// A cross-section's figures as a check or study quantity (see MeasureSection.hpp).
#include "problems/run/MeasureSection.hpp"

#include <stdexcept>
#include <string>

#include "fem/model/LineElement.hpp"

namespace beamrotor {

namespace {

double catalogueProperty(const CatalogProperties& p, const std::string& name) {
  if (name == "A") return p.A;
  if (name == "Iy") return p.Iy;
  if (name == "Iz") return p.Iz;
  if (name == "It") return p.It;
  if (name == "Wel_y") return p.Wely;
  if (name == "Wel_z") return p.Welz;
  if (name == "Wpl_y") return p.Wply;
  return p.Wplz;  // the reader admits no other name (kSectionProperties)
}

/// The same from the model's section: local z is the tables' y-y.
double ownProperty(const Section& s, const Quantity& q) {
  const std::string& name = q.property;
  if (name == "A") return s.A;
  if (name == "Iy") return s.Iz;
  if (name == "Iz") return s.Iy;
  if (name == "It") return s.J;
  const double outer = name == "Wel_y" ? s.outerY : name == "Wel_z" ? s.outerZ : 0;
  if (outer > 0) return (name == "Wel_y" ? s.Iz : s.Iy) / outer;
  throw std::invalid_argument(
      "'" + q.text + "': section '" + q.target + "' " +
      (name.starts_with("Wpl") ? "is not from the catalogue; only catalogue sections give Wpl"
                               : "has no known extent (give its depth and width)"));
}

}  // namespace

double measureSection(const Quantity& q, const Model& model,
                      const std::vector<DeckCatalogSection>& catalogue) {
  for (const DeckCatalogSection& s : catalogue)
    if (s.name == q.target) return catalogueProperty(s.properties, q.property);
  for (const auto& e : model.elements())
    if (const LineElement* line = asLine(e); line && line->section().name == q.target)
      return ownProperty(line->section(), q);
  throw std::invalid_argument("'" + q.text + "': no beam of the model has section '" + q.target +
                              "'");
}

}  // namespace beamrotor
