// Greedy label placement (see LabelPlacement.hpp).
#include "problems/output/files/LabelPlacement.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace beamrotor {

std::vector<PixelBox> placeLabels(const std::vector<PointLabel>& labels, const PixelBox& plot) {
  constexpr double kGap = 7;      // between the point and its label (px)
  constexpr double kMarker = 5;   // half the size of a marked point (px)
  std::vector<PixelBox> points;
  for (const PointLabel& l : labels)
    points.push_back({l.x - kMarker, l.y - kMarker, l.x + kMarker, l.y + kMarker});

  std::vector<PixelBox> placed;
  for (const PointLabel& l : labels) {
    // Offsets of the box's top-left corner from the point, in order of preference.
    const double right = kGap, left = -kGap - l.width;
    const double below = 2, above = -2 - l.height;
    std::vector<std::pair<double, double>> candidates{
        {right, below}, {right, above}, {left, below}, {left, above}};
    for (int k = 1; k <= 4; ++k) {
      candidates.push_back({right, below + k * l.height});
      candidates.push_back({right, above - k * l.height});
      candidates.push_back({left, below + k * l.height});
      candidates.push_back({left, above - k * l.height});
    }
    std::optional<PixelBox> firstInside, chosen;
    for (const auto& [dx, dy] : candidates) {
      const PixelBox box{l.x + dx, l.y + dy, l.x + dx + l.width, l.y + dy + l.height};
      if (!box.inside(plot)) continue;
      if (!firstInside) firstInside = box;
      const auto hits = [&](const PixelBox& o) { return box.overlaps(o); };
      if (std::none_of(placed.begin(), placed.end(), hits) &&
          std::none_of(points.begin(), points.end(), hits)) {
        chosen = box;
        break;
      }
    }
    placed.push_back(chosen        ? *chosen
                     : firstInside ? *firstInside
                                   : PixelBox{l.x + right, l.y + below, l.x + right + l.width,
                                              l.y + below + l.height});
  }
  return placed;
}

}  // namespace beamrotor
