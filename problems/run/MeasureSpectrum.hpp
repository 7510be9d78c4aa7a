// Measuring the response-spectrum check quantities (problems/deck/structure/SpectrumQuantity.hpp)
// in a solved response-spectrum analysis: combined peaks and effective masses.
#pragma once

#include "fem/modal/BaseMotion.hpp"
#include "fem/modal/ResponseSpectrum.hpp"
#include "fem/model/Model.hpp"
#include "problems/deck/Quantity.hpp"

namespace beamrotor {

/// The value of a `spectrum ...`, `effective_mass N DIR` or `captured_mass DIR` quantity.
/// Throws std::invalid_argument for a name or dof the result lacks, or too few modes.
double measureSpectrum(const Quantity& q, const ResponseSpectrumResult& r, const Model& model);

/// The value of a `base_motion ...` quantity: the largest over the frequencies, or the
/// frequency of the largest transmissibility. Throws std::invalid_argument for an unknown point.
double measureBaseMotion(const Quantity& q, const BaseMotionResult& r, const Model& model);

}  // namespace beamrotor
