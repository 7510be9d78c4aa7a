// An unloaded plain journal bearing (a vertical rotor's, or any journal whose static load is
// zero): the journal runs centred in its clearance, and the film's linear coefficients are
// the short-bearing theory's (elements/PlainJournalBearing.hpp) in their limit eps -> 0.
//
// There W -> 0 with eps: S_s = (1 - eps^2)^2 / (eps sqrt(16 eps^2 + pi^2 (1 - eps^2))) ->
// 1 / (pi eps), so W -> pi mu Omega D L^3 eps / (8 c^2), and h0 -> pi^-3. The direct
// stiffnesses vanish with W; what stays is a cross-coupled stiffness and a direct damping,
//   kyz = -kzy = pi mu Omega D L^3 / (8 c^3) = pi mu Omega R L^3 / (4 c^3),
//   cyy = czz  = pi mu D L^3 / (4 c^3)       = pi mu R L^3 / (2 c^3),
//   kyy = kzz = cyz = czy = 0,
// (Childs, Turbomachinery Rotordynamics, 1993, sec. 3.4: a centred short bearing whose
// cross-coupled stiffness is Omega / 2 times its damping, the half-frequency whirl ratio of
// oil whirl). Isotropic, so the load direction does not matter.
#pragma once

#include "elements/PlainJournalBearing.hpp"

namespace beamrotor {

/// The coefficients of the centred journal at spin speed Omega (rad/s); the load is not read.
BearingCoefficients concentricJournalCoefficients(const PlainJournal& bearing, double speed);

}  // namespace beamrotor
