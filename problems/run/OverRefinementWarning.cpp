#include "problems/run/OverRefinementWarning.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "fem/model/LineElement.hpp"

namespace beamrotor {

std::optional<std::string> overRefinementWarning(const Model& model, const StaticResult& r) {
  double shortest = std::numeric_limits<double>::infinity(), total = 0;
  for (const auto& e : model.elements())
    if (const LineElement* line = asLine(e)) {
      shortest = std::min(shortest, line->length());
      total += line->length();
    }
  if (total <= 0) return std::nullopt;  // no beams
  const double discretisation = (shortest / total) * (shortest / total) / 3;
  if (!(r.roundOff > discretisation)) return std::nullopt;
  char text[400];
  std::snprintf(text, sizeof text,
                "mesh past the point where round-off outweighs discretisation error: the "
                "solution's round-off error, bounded by measurement at %.2g%s, exceeds "
                "(h/L)^2 / 3 = %.2g (smallest element %.3g m of %.3g m of beams); fewer "
                "elements would be as accurate or better",
                r.roundOff, r.roundOff >= 1 ? " (no digit of the solution can be trusted)" : "",
                discretisation, shortest, total);
  return std::string(text);
}

}  // namespace beamrotor
