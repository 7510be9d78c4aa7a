// Labels beside marked points on a chart, placed so that no two overlap and none leaves the
// plot: the critical speeds of a Campbell diagram sit close together whenever two whirl
// lines cross the speed line near each other (1812 and 1988 rpm, say).
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

/// A rectangle in canvas pixels, y downwards.
struct PixelBox {
  double left = 0, top = 0, right = 0, bottom = 0;
  bool overlaps(const PixelBox& o) const {
    return left < o.right && o.left < right && top < o.bottom && o.top < bottom;
  }
  bool inside(const PixelBox& o) const {
    return left >= o.left && right <= o.right && top >= o.top && bottom <= o.bottom;
  }
};

/// A label to place: the point it belongs to (pixels) and its size.
struct PointLabel {
  double x = 0, y = 0;  ///< the marked point
  double width = 0, height = 0;
};

/// For each label, in order, the first of a fixed list of places around its point (right
/// below, right above, left below, left above, then further down and up) that stays inside
/// `plot`, overlaps no label placed before and covers no marked point; when none is free, the
/// first that stays inside. Returns the boxes, in the labels' order.
std::vector<PixelBox> placeLabels(const std::vector<PointLabel>& labels, const PixelBox& plot);

}  // namespace beamrotor
