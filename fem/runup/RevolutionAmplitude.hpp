// The amplitude of a whirling node, one value per revolution of the shaft: what a run-up's
// amplitude-against-speed chart plots (the tracking filter of a coast-down measurement, in
// the time domain). Over each revolution (the spin angle passing a multiple of 2 pi) the
// amplitude is half the orbit's longest chord, the largest distance between two of its
// positions over two: the semi-major axis of a steady elliptical orbit (to the sampling of the
// revolution), and for any orbit a width that a static offset (the sag under gravity) does
// not change. The half peak-to-peak of uy and of uz are kept too.
#pragma once

#include <vector>

namespace beamrotor {

/// One node's amplitudes, one entry per completed revolution.
struct RevolutionAmplitudes {
  std::vector<double> speed;      ///< mean spin speed over the revolution (rad/s)
  std::vector<double> time;       ///< end of the revolution (s)
  std::vector<double> amplitude;  ///< half the longest chord of the revolution's orbit (m)
  std::vector<double> halfRangeY, halfRangeZ;  ///< (max - min) / 2 of uy, of uz (m)
};

class RevolutionAmplitude {
 public:
  /// Adds the position (y, z) (m) at time t (s), spin angle phi (rad) and speed (rad/s);
  /// samples come in time order, the first at the start of the run.
  void add(double t, double phi, double speed, double y, double z);
  const RevolutionAmplitudes& amplitudes() const { return out_; }

 private:
  void closeRevolution(double t);

  long long revolution_ = -1;  ///< floor(phi / 2 pi) of the samples held
  std::vector<double> y_, z_, speed_;
  RevolutionAmplitudes out_;
};

}  // namespace beamrotor
