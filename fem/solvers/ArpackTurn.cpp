#include "fem/solvers/ArpackTurn.hpp"

namespace beamrotor {

namespace {

std::mutex& arpackState() {
  static std::mutex state;
  return state;
}

}  // namespace

ArpackTurn::ArpackTurn() : held_(arpackState()) {}

}  // namespace beamrotor
