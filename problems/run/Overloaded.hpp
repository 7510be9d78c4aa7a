// One visitor from several lambdas, for std::visit over a result's kinds (RunResult.hpp): a
// kind without its lambda does not compile, so no writer forgets a new kind.
#pragma once

namespace beamrotor {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

}  // namespace beamrotor
