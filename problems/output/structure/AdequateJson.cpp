#include "problems/output/structure/AdequateJson.hpp"

namespace beamrotor {

Json adequateJson(const AdequateChoice& c) {
  Json doc;
  doc["target"] = c.target;
  doc["formulation"] = c.formulation;
  doc["deck_formulation"] = c.deckFormulation;
  doc["elements_per_segment"] = c.elementsPerSegment;
  doc["elements"] = c.elements;
  doc["dofs"] = c.dofs;
  doc["estimated_error"] = c.estimatedError;
  doc["mesh_error"] = c.meshError;
  doc["shear_contribution"] = c.shearContribution ? Json(*c.shearContribution) : Json(nullptr);
  doc["seconds"] = c.seconds;
  doc["search_seconds"] = c.searchSeconds;
  doc["fixed_mesh"] = {
      {"elements", c.deckElements}, {"dofs", c.deckDofs}, {"seconds", c.deckSeconds}};
  doc["dofs_saved"] = c.deckDofs - c.dofs;
  doc["time_ratio"] = c.deckSeconds > 0 ? c.seconds / c.deckSeconds : 0.0;
  if (c.rigidBodyError)
    doc["rigid_body"] = {{"error", *c.rigidBodyError}, {"adequate", c.rigidBodyAdequate}};
  return doc;
}

}  // namespace beamrotor
