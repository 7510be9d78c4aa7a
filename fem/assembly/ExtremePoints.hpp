// Which of a set of points are extreme points of their convex hull: the points no weighted
// average of the others reaches. A linear function's largest and smallest value over the set
// are taken at extreme points (and a convex function's largest), so where many linear
// combinations of a few vectors are searched for the largest of something (load combinations
// of load cases), the others need not be evaluated.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace beamrotor {

/// One flag per row of `points` (each row a point): true unless the point repeats an earlier
/// row exactly or is shown to be a convex combination of the other points (weights >= 0 that
/// sum to 1 found by a small linear programme and checked: their combination within 1e-12 of
/// the largest coordinate). A point that could not be shown inside is kept, so a false flag is
/// always proven; so is every point not yet tested when the programmes' work reaches about a
/// tenth of a second (thousands of points of many coordinates, most of them extreme). The
/// first of several equal points is kept.
std::vector<bool> extremePoints(const Eigen::MatrixXd& points);

}  // namespace beamrotor
