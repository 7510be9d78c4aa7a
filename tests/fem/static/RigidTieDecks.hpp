// What the rigid-tie tests share: the steel bar their decks are built of, and numbers written
// into deck text at full precision.
#pragma once

#include <sstream>
#include <string>

namespace beamrotor::test::ties {

inline constexpr double kE = 210e9, kNu = 0.3, kD = 0.1;  // steel, a round bar 100 mm across

/// v with 17 significant digits (a double read back exactly).
inline std::string fmt(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

}  // namespace beamrotor::test::ties
