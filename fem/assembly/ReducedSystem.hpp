// Constraint elimination as a matched pair: form the reduced right-hand side from the
// prescribed values, and map a full-length solution back onto the nodes.
#pragma once

#include <Eigen/Dense>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

class Model;

/// Full-length vector holding the supports' prescribed values at constrained dofs, zero
/// elsewhere.
Eigen::VectorXd prescribedValues(const Model& model, const DofMap& dofs);

/// f_F - K_FC u_C: the free part of the loads minus what the prescribed displacements
/// (given in the full-length uPrescribed) push onto the free dofs; made in f's storage.
Eigen::VectorXd reducedRightHandSide(const Model& model, const DofMap& dofs, Eigen::VectorXd f,
                                     const Eigen::VectorXd& uPrescribed);

/// A full-length vector laid out per node (absent dofs zero).
NodalField toNodalField(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u);

/// The inverse of toNodalField: a full-length vector (ordered as DofMap) from a field per node.
Eigen::VectorXd fromNodalField(const DofMap& dofs, const NodalField& field);

/// A free-length vector (e.g. a mode shape) laid out per node; constrained dofs get zero.
NodalField freeToNodalField(const Model& model, const DofMap& dofs, const Eigen::VectorXd& uf);

/// stiffnessEntries: stored entries of the free-free K (both triangles).
SystemSize systemSize(const Model& model, const DofMap& dofs, long long stiffnessEntries,
                      double factorEntries);

}  // namespace beamrotor
