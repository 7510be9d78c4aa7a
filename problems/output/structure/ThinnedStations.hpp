// A long line's samples thinned to what a chart and a reader need: a line of 10^5 elements
// sampled at 5 stations an element is half a million rows, 110 MB of CSV and a chart no
// screen can show. The exact peaks are results.json's (element peaks), not the samples'.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "problems/output/structure/LineSampling.hpp"

namespace beamrotor {

/// Stations a fields table holds by default: about three a pixel across a wide chart.
inline constexpr std::size_t kTableStations = 4000;

/// `stations` when there are at most `most`; otherwise every k-th of them (k the smallest step
/// that leaves about `most`), the last one, and both sides of every jump (two stations at one
/// place along the line whose stresses or section forces differ by more than 1e-6 of their
/// largest: a step of the section, a point load), so that the diagrams keep their steps.
std::vector<StaticStation> thinnedStations(const std::vector<StaticStation>& stations,
                                           std::size_t most = kTableStations);

}  // namespace beamrotor
