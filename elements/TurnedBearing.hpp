// A bearing whose own axes are turned about the shaft: the load of a journal acting at any
// angle, not only along -y.
//
// Bearing data are given in the bearing's axes (x_b, y_b), the static load along -x_b
// (elements/Bearing.hpp, elements/PlainJournalBearing.hpp). With those axes turned by the
// angle theta about +x, from +y towards +z (the sense of rotation), x_b = (cos, sin) theta and
// y_b = (-sin, cos) theta in global (y, z), and a force -K u in the bearing's axes is -T K T^T u
// in global ones, T = [cos -sin; sin cos] (likewise for C). Turning a rotor and its bearings
// together changes none of its eigenvalues: an axisymmetric shaft's matrices commute with T.
#pragma once

#include "elements/Bearing.hpp"

namespace beamrotor {

/// T K T^T and T C T^T for the bearing's axes turned by `angle` (rad) from (y, z).
BearingCoefficients turnedCoefficients(const BearingCoefficients& k, double angle);

}  // namespace beamrotor
