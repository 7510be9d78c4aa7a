// A start vector for ARPACK that is the same on every run.
#pragma once

#include <Eigen/Dense>
#include <random>

namespace beamrotor {

/// A starting vector that depends only on its length and `seed`: entries in [-1, 1) from the
/// minimal standard generator (Park and Miller; its sequence is fixed by the C++ standard).
/// ARPACK's own random start (info = 0) continues a generator kept between calls, so its
/// result (the basis it returns for a double eigenvalue, the number of steps it takes) would
/// depend on every ARPACK call made before in the process: the planar benchmark took 51 steps
/// in one run and 72 in the next. Pseudo-random, not constant: a constant vector is orthogonal
/// to the antisymmetric modes of a symmetric structure. Another `seed` gives another vector.
inline Eigen::VectorXd fixedStart(Eigen::Index size, unsigned seed = 20261124u) {
  std::minstd_rand generator(seed);
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i)
    v[i] = 2.0 * double(generator() - generator.min()) /
               double(generator.max() - generator.min() + 1) -
           1;
  return v;
}

}  // namespace beamrotor
