// Element recovery: stress resultants and outer-fibre stress at stations along every line
// element, from a solved displacement field.
#pragma once

#include <vector>

#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// Fields at one station of one line element.
struct BeamStation {
  int element = -1;          ///< index into model.elements()
  double s = 0;              ///< fraction of the element's length, 0..1
  Eigen::Vector3d position;  ///< global coordinates (m)
  SectionForces forces;      ///< local frame, see SectionForces
  double stress = 0;         ///< largest |normal stress| on the outer fibres (Pa)
  double shear = 0;          ///< largest transverse shear stress (Pa), see maxShearStress
};

/// Samples every line element at `perElement` + 1 evenly spaced stations (ends included),
/// in element order. Other elements (springs, masses) are skipped.
std::vector<BeamStation> recoverBeamFields(const Model& model, const NodalField& displacement,
                                           int perElement = 1);

}  // namespace beamrotor
