// The tilting-pad bearing the tests share: a 100 mm journal, L/D 0.5, on four 80 deg pads
// with preload 0.3, the load between two of them (the shipped compressor's pad geometry).
#pragma once

#include <numbers>

#include "elements/TiltingPadBearing.hpp"

namespace beamrotor::test {

inline PlainJournal tiltingPadTestJournal() {
  PlainJournal j;
  j.diameter = 0.1;
  j.length = 0.05;
  j.clearance = 100e-6;
  j.viscosity = 0.02;
  j.load = 5000;
  return j;
}

inline TiltingPads fourPadsBetween() {
  TiltingPads p;
  p.count = 4;
  p.arc = 80 * std::numbers::pi / 180;
  p.pivotOffset = 0.5;
  p.preload = 0.3;
  p.loadOnPad = false;
  return p;
}

}  // namespace beamrotor::test
