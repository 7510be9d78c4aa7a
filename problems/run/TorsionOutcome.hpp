// A torsion analysis, solved: the shaft line's model in twist alone and its modes. The model
// is its own (one dof per node, rx), so writers draw the shapes on it, not on the deck's.
#pragma once

#include <memory>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

struct TorsionOutcome {
  std::shared_ptr<const Model> model;  ///< the line in twist: rx at every node
  ModalResult modes;
  bool free = false;  ///< no support holds the twist: the first mode is the train's rotation
};

}  // namespace beamrotor
