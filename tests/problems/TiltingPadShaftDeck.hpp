// The short shaft the tilting-pad deck tests solve: 0.4 m of 100 mm steel in four elements, a
// 50 kg disk at its end, a four-pad tilting-pad bearing A at its start (80 deg pads, preload
// 0.3, load between pads, 5000 N; table 3000 to 6000 rpm) and a stiff damped support B at the
// end; deck text up to `analyses:`.
#pragma once

#include <string>

namespace beamrotor::test {

/// The deck with `choice` (e.g. ", pad_tilts: dofs") added to bearing A's keys.
inline std::string tiltingPadShaftDeck(const std::string& title, const std::string& choice) {
  return "title: " + title + R"(
model: {dimension: lateral}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.4, section: shaft, elements: 4}]
masses: [{name: disk, at: end, m: 50}]
bearings:
  - {name: A, at: start, type: tilting-pad, D: 100 mm, L: 50 mm, c: 100 um, mu: 0.02 Pa s,
     from_rpm: 3000, to_rpm: 6000, steps: 1, load: 5000 N, arc: 80 deg, preload: 0.3, pads: 4,
     orientation: load-between-pads)" +
         choice + R"(}
  - {name: B, at: end, kxx: 1e8, kyy: 1e8, cxx: 1e3, cyy: 1e3}
)";
}

}  // namespace beamrotor::test
