// The lines of a Campbell diagram followed to speeds between two of its sweep speeds, where a
// result is refined on the speed itself (the onset of instability, a critical speed). At each
// speed as many modes are solved as the diagram's widest speed had, and every line takes the
// candidate whose shape correlates best (MAC) with the line's mode at the interval's lower
// speed. That mode is solved once more here and recognised by its eigenvalue, since the
// diagram keeps no shapes.
#pragma once

#include <cstddef>
#include <vector>

#include "fem/rotor/RotorModes.hpp"

namespace beamrotor {

class LineFollower {
 public:
  /// Follows `campbell`'s lines from its speed index `from`; `options` must be the diagram's.
  /// The model must outlive this.
  LineFollower(const Model& model, const CampbellResult& campbell, const RotorOptions& options,
               std::size_t from);

  /// Each line's mode at `speed` (rad/s, near the interval), without shapes.
  std::vector<RotorMode> at(double speed);
  /// Eigen-solutions so far, the one at the lower speed included.
  int evaluations() const { return evaluations_; }

 private:
  RotorModesResult solve(double speed);

  RotorSystem system_;
  RotorOptions options_;
  int lines_ = 0;
  QuadraticEigenSolver solver_;
  Eigen::MatrixXcd anchor_;  ///< each line's vector at the lower speed
  int evaluations_ = 0;
};

}  // namespace beamrotor
