#include "fem/modal/DesignSpectrum.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace beamrotor {

SpectrumCorners en1998Corners(int type, GroundType ground) {
  // EN 1998-1:2004 Table 3.2 (type 1) and Table 3.3 (type 2): S, TB, TC, TD for A..E.
  static constexpr SpectrumCorners type1[] = {{1.0, 0.15, 0.4, 2.0},
                                              {1.2, 0.15, 0.5, 2.0},
                                              {1.15, 0.20, 0.6, 2.0},
                                              {1.35, 0.20, 0.8, 2.0},
                                              {1.4, 0.15, 0.5, 2.0}};
  static constexpr SpectrumCorners type2[] = {{1.0, 0.05, 0.25, 1.2},
                                              {1.35, 0.05, 0.25, 1.2},
                                              {1.5, 0.10, 0.25, 1.2},
                                              {1.8, 0.10, 0.30, 1.2},
                                              {1.6, 0.05, 0.25, 1.2}};
  if (type != 1 && type != 2) throw std::invalid_argument("EN 1998-1 spectrum type is 1 or 2");
  return (type == 1 ? type1 : type2)[int(ground)];
}

DesignSpectrum DesignSpectrum::en1998Vertical(int type, double ag, double dampingRatio) {
  if (type != 1 && type != 2) throw std::invalid_argument("EN 1998-1 spectrum type is 1 or 2");
  DesignSpectrum s = en1998(type, GroundType::A, (type == 1 ? 0.90 : 0.45) * ag, dampingRatio);
  s.vertical_ = true;
  s.corners_ = {1.0, 0.05, 0.15, 1.0};  // Table 3.4: S plays no part
  s.plateauFactor_ = 3.0;
  return s;
}

double en1998DampingCorrection(double dampingRatio) {
  return std::max(0.55, std::sqrt(10 / (5 + 100 * dampingRatio)));
}

DesignSpectrum DesignSpectrum::en1998(int type, GroundType ground, double ag,
                                      double dampingRatio) {
  DesignSpectrum s;
  s.type_ = type;
  s.ground_ = ground;
  s.corners_ = en1998Corners(type, ground);
  s.ag_ = ag;
  s.damping_ = dampingRatio;
  s.eta_ = en1998DampingCorrection(dampingRatio);
  return s;
}

DesignSpectrum DesignSpectrum::table(std::vector<double> periods,
                                     std::vector<double> accelerations) {
  if (periods.empty() || periods.size() != accelerations.size())
    throw std::invalid_argument("a spectrum table needs as many accelerations as periods");
  for (std::size_t i = 1; i < periods.size(); ++i)
    if (!(periods[i] > periods[i - 1]))
      throw std::invalid_argument("a spectrum table's periods must ascend");
  DesignSpectrum s;
  s.periods_ = std::move(periods);
  s.accelerations_ = std::move(accelerations);
  return s;
}

bool DesignSpectrum::covers(double T) const {
  return !isTable() || (T >= periods_.front() && T <= periods_.back());
}

double DesignSpectrum::at(double T) const {
  if (isTable()) {
    const auto& P = periods_;
    if (T <= P.front()) return accelerations_.front();
    const std::size_t i = std::upper_bound(P.begin(), P.end(), T) - P.begin();
    if (i >= P.size()) return accelerations_.back();
    const double w = (T - P[i - 1]) / (P[i] - P[i - 1]);
    return (1 - w) * accelerations_[i - 1] + w * accelerations_[i];
  }
  // EN 1998-1:2004 (3.2)-(3.5), or (3.8)-(3.11) with S = 1 and 3.0 for 2.5; the last branch
  // is carried past 4 s.
  const auto [S, TB, TC, TD] = corners_;
  const double plateau = ag_ * S * eta_ * plateauFactor_;
  if (T <= TB) return ag_ * S * (1 + T / TB * (eta_ * plateauFactor_ - 1));
  if (T <= TC) return plateau;
  if (T <= TD) return plateau * TC / T;
  return plateau * TC * TD / (T * T);
}

std::string DesignSpectrum::describe() const {
  std::ostringstream text;
  if (isTable()) {
    text << "table of " << periods_.size() << " periods, " << periods_.front() << " to "
         << periods_.back() << " s";
    return text.str();
  }
  static constexpr const char* grounds = "ABCDE";
  if (vertical_) {
    text << "EN 1998-1 type " << type_ << " vertical, avg = " << ag_ << " m/s^2, "
         << 100 * damping_ << " % damping (eta = " << eta_ << ")";
    return text.str();
  }
  text << "EN 1998-1 type " << type_ << ", ground " << grounds[int(ground_)] << ", ag = " << ag_
       << " m/s^2, " << 100 * damping_ << " % damping (eta = " << eta_ << ")";
  return text.str();
}

std::vector<double> DesignSpectrum::breakPeriods() const {
  if (isTable()) return periods_;
  return {0, corners_.TB, corners_.TC, corners_.TD};
}

}  // namespace beamrotor
