// Solving a study's points on this machine: one after the other, or on several threads that
// take chunks of points from a shared counter as they finish the last (dynamic balancing:
// points differ in cost), while the calling thread hands the rows on in point order. Rows
// finished ahead of the next one wait in a bounded buffer; nothing else is kept. A study
// asked to stop starts no new point: the points in progress finish and every finished row is
// handed on, so the rows handed on may then leave gaps.
#pragma once

#include <functional>

#include "problems/study/DesignPoints.hpp"
#include "problems/study/PointRanges.hpp"
#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

/// Receives each row, in increasing point order.
using RowSink = std::function<void(const StudyRow&)>;

/// Asked before each point is started (from any thread): true stops the study there.
using StopRequest = std::function<bool()>;

/// The points of `todo` with `threads` threads (1: on the calling thread). An exception from
/// sink stops the workers and propagates.
void solvePoints(const StudyPlan& plan, const DesignPoints& points, const PointRanges& todo,
                 int threads, const RowSink& sink, const StopRequest& stop);

/// The chunk a worker takes at once: enough to make the shared counter's traffic negligible,
/// few enough that the last chunks balance the workers (about 64 chunks per worker).
long long studyChunk(long long points, int workers);

}  // namespace beamrotor
