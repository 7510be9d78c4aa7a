#include "problems/run/OverRefinementWarning.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "fem/model/LineElement.hpp"

namespace beamrotor {

std::optional<std::string> overRefinementWarning(const Model& model, const StaticResult& r) {
  double shortest = std::numeric_limits<double>::infinity(), total = 0;
  for (const auto& e : model.elements())
    if (const auto* line = dynamic_cast<const LineElement*>(e.get())) {
      shortest = std::min(shortest, line->length());
      total += line->length();
    }
  if (total <= 0 || r.rcond <= 0) return std::nullopt;  // no beams, or singular (refused)
  const double roundOff = std::numeric_limits<double>::epsilon() / r.rcond;
  const double discretisation = (shortest / total) * (shortest / total) / 3;
  if (roundOff <= discretisation) return std::nullopt;
  char text[320];
  std::snprintf(text, sizeof text,
                "mesh past the point where round-off outweighs discretisation error: "
                "eps / rcond = %.2g exceeds (h/L)^2 / 3 = %.2g (smallest element %.3g m of "
                "%.3g m of beams); fewer elements would be as accurate or better",
                roundOff, discretisation, shortest, total);
  return std::string(text);
}

}  // namespace beamrotor
