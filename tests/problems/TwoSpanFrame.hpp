// The planar frame the moving-load deck tests cross: two equal spans of L = 6 m (span1 from A
// to B, span2 from B to C) on pins at A, B and C, a point m1 at mid-span of span1, a steel
// section of 53.8 cm^2 and 8356 cm^4; deck text up to its supports.
#pragma once

#include <string>

namespace beamrotor::test {

/// The frame with `elements` elements per span.
inline std::string twoSpanFrame(int elements) {
  const std::string n = std::to_string(elements);
  return "parameters: {L: 6 m}\n"
         "model: {dimension: planar}\n"
         "materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]\n"
         "sections: [{name: s, shape: general, A: 53.8 cm^2, I: 8356 cm^4, depth: 300 mm, "
         "width: 150 mm}]\n"
         "nodes:\n"
         "  - {name: A, at: [0, 0]}\n"
         "  - {name: B, at: [L, 0]}\n"
         "  - {name: C, at: [2 * L, 0]}\n"
         "members:\n"
         "  - {name: span1, from: A, to: B, section: s, elements: " + n + "}\n"
         "  - {name: span2, from: B, to: C, section: s, elements: " + n + "}\n"
         "points: [{name: m1, member: span1, at: 0.5}]\n"
         "supports:\n"
         "  - {name: A, at: A, fix: pinned}\n"
         "  - {name: B, at: B, fix: [uy]}\n"
         "  - {name: C, at: C, fix: [uy]}\n";
}

}  // namespace beamrotor::test
