#include "problems/output/structure/ThinnedStations.hpp"

#include <algorithm>
#include <cmath>

namespace beamrotor {

namespace {

/// What a station's diagrams show, each as a reader compares them: normal and shear stress,
/// the section forces.
std::array<double, 8> shown(const StaticStation& s) {
  return {s.stress, s.shear, s.forces.N, s.forces.Vy, s.forces.Vz, s.forces.T, s.forces.My,
          s.forces.Mz};
}

}  // namespace

std::vector<StaticStation> thinnedStations(const std::vector<StaticStation>& stations,
                                           std::size_t most) {
  if (stations.size() <= most || most < 2) return stations;
  // A jump: two stations at one place whose values differ by more than round-off of the
  // largest value along the line (at a joint of equal elements they differ by round-off).
  std::array<double, 8> largest{};
  for (const StaticStation& s : stations) {
    const auto v = shown(s);
    for (std::size_t k = 0; k < v.size(); ++k) largest[k] = std::max(largest[k], std::abs(v[k]));
  }
  const auto jumps = [&](const StaticStation& a, const StaticStation& b) {
    if (a.place.x != b.place.x) return false;
    const auto u = shown(a), v = shown(b);
    for (std::size_t k = 0; k < u.size(); ++k)
      if (std::abs(u[k] - v[k]) > 1e-6 * largest[k]) return true;
    return false;
  };
  std::vector<bool> jumpAt(stations.size(), false);
  std::size_t jumpStations = 0;
  for (std::size_t i = 1; i < stations.size(); ++i)
    if (jumps(stations[i - 1], stations[i])) {
      jumpStations += !jumpAt[i - 1] + !jumpAt[i];
      jumpAt[i - 1] = jumpAt[i] = true;
    }
  // Every k-th station and the last, with room left for the jumps' stations.
  const std::size_t room = most > jumpStations + 2 ? most - jumpStations - 1 : 1;
  const std::size_t step = (stations.size() + room - 1) / room;
  std::vector<StaticStation> kept;
  for (std::size_t i = 0; i < stations.size(); ++i)
    if (i % step == 0 || i + 1 == stations.size() || jumpAt[i]) kept.push_back(stations[i]);
  return kept;
}

}  // namespace beamrotor
