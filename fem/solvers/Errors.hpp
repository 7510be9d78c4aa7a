// Errors the analyses raise. Each message is meant for the user as it stands.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "fem/model/Dof.hpp"

namespace beamrotor {

/// An analysis could not produce a trustworthy result (singular system, no convergence...).
class SolveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A matrix that had to be factorised is singular to working precision (e.g. K - sigma M with
/// sigma on an eigenvalue, or K of a mechanism at sigma = 0).
class SingularSystem : public SolveError {
 public:
  using SolveError::SolveError;
};

/// The structure can move without straining: the listed dofs take part in a zero-energy mode.
class UnsupportedStructure : public SolveError {
 public:
  UnsupportedStructure(const std::string& message, std::vector<NodeDof> freeDofs)
      : SolveError(message), freeDofs_(std::move(freeDofs)) {}
  const std::vector<NodeDof>& freeDofs() const { return freeDofs_; }

 private:
  std::vector<NodeDof> freeDofs_;
};

}  // namespace beamrotor
