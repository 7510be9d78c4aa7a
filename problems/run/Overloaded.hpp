// One visitor from several lambdas, for std::visit over a result's kinds (RunResult.hpp): a
// kind without its lambda does not compile, so no writer forgets a new kind.
#pragma once

namespace beamrotor {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

/// Said for clang 14 (the fuzz build's), which does not deduce an aggregate's arguments.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace beamrotor
