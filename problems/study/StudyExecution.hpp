// Solving a study's points on this machine: one after the other, or on several threads that
// take chunks of points from a shared counter as they finish the last (dynamic balancing:
// points differ in cost), while the calling thread hands the rows on in point order. Rows
// finished ahead of the next one wait in a bounded buffer; nothing else is kept.
#pragma once

#include <functional>

#include "problems/study/DesignPoints.hpp"
#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

/// Receives each row, in point order.
using RowSink = std::function<void(const StudyRow&)>;

/// Points [0, points.size()) with `threads` threads (1: on the calling thread). An exception
/// from sink stops the workers and propagates.
void solvePoints(const StudyPlan& plan, const DesignPoints& points, int threads,
                 const RowSink& sink);

/// The chunk a worker takes at once: enough to make the shared counter's traffic negligible,
/// few enough that the last chunks balance the workers (about 64 chunks per worker).
long long studyChunk(long long points, int workers);

}  // namespace beamrotor
