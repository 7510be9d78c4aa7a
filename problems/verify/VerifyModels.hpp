// Small models the failure-case studies share, built the way decks build them (LineBuilder).
#pragma once

#include <memory>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"
#include "meshes/LineBuilder.hpp"

namespace beamrotor::verify {

/// A steel rectangle b x h (E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3).
std::shared_ptr<const Section> steelRectangle(double b, double h);

/// A uniform planar beam of length L along x with n elements; points "start" and "end".
/// When `clampStart`, every planar dof of the first node is fixed (support "root").
Line planarBeam(Model& model, double L, std::shared_ptr<const Section> section, int n,
                BeamOptions options = {}, bool clampStart = true);

}  // namespace beamrotor::verify
