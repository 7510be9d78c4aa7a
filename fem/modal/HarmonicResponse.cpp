#include "fem/modal/HarmonicResponse.hpp"

#include <Eigen/SparseLU>
#include <sstream>

#include "fem/solvers/Errors.hpp"

namespace beamrotor {

HarmonicResponse::HarmonicResponse(const Model& model, double alpha, double beta)
    : model_(model), dofs_(model), ties_(model, dofs_) {
  SparseAssembler assembler(model, dofs_);
  K_ = ties_.stiffness(assembler.assemble(MatrixKind::stiffness));
  fullMass_ = assembler.assemble(MatrixKind::mass);
  M_ = ties_.projected(fullMass_);
  C_ = ties_.projected(assembler.assemble(MatrixKind::damping));
  if (alpha != 0) C_ += alpha * M_;
  if (beta != 0) C_ += beta * K_;
}

ComplexVector HarmonicResponse::solve(double w, const ComplexVector& f) const {
  using Complex = std::complex<double>;
  const Eigen::SparseMatrix<Complex> Z = K_.cast<Complex>() - Complex(w * w) * M_.cast<Complex>() +
                                         Complex(0, w) * C_.cast<Complex>();
  Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu;
  lu.compute(Z);
  const int n = dofs_.freeCount();
  ComplexVector x = ComplexVector::Zero(dofs_.size());
  if (lu.info() == Eigen::Success) {
    const ComplexVector reduced = ties_.empty() ? ComplexVector(f.head(n))
                                                : ComplexVector(ties_.loads(f.real()).cast<Complex>() +
                                                                Complex(0, 1) * ties_.loads(f.imag()));
    x.head(n) = ties_.expand(ComplexVector(lu.solve(reduced)));
  }
  if (lu.info() != Eigen::Success || !x.allFinite()) {
    std::ostringstream why;
    why << "the dynamic stiffness K - w^2 M + i w C is singular at w = " << w
        << " rad/s: an undamped natural frequency lies there";
    throw SingularSystem(why.str());
  }
  return x;
}

}  // namespace beamrotor
