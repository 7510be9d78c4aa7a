#include "problems/output/structure/MatrixExport.hpp"

#include <stdexcept>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/FileWriting.hpp"

namespace beamrotor {

namespace fs = std::filesystem;

namespace {

/// Matrix Market coordinate format, 1-based, every stored entry (what Eigen::loadMarket and
/// scipy.io.mmread read).
void writeMarket(const SparseMatrix& A, const fs::path& file) {
  writeFile(file, [&](std::ostream& out) {
    out << "%%MatrixMarket matrix coordinate real general\n"
        << A.rows() << " " << A.cols() << " " << A.nonZeros() << "\n";
    for (int k = 0; k < A.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(A, k); it; ++it)
        out << it.row() + 1 << " " << it.col() + 1 << " " << exactDecimal(it.value()) << "\n";
  });
}

/// Matrix Market array format: a column vector.
void writeMarket(const Eigen::VectorXd& v, const fs::path& file) {
  writeFile(file, [&](std::ostream& out) {
    out << "%%MatrixMarket matrix array real general\n" << v.size() << " 1\n";
    for (Eigen::Index i = 0; i < v.size(); ++i) out << exactDecimal(v[i]) << "\n";
  });
}

/// row -> node, point name, dof and node position, so a user can find an entry's meaning.
CsvTable dofTable(const Model& model, const DofMap& dofs) {
  CsvTable table(
      kDofsCsv,
      {{"row", ""}, {"node", ""}, {"point", ""}, {"dof", ""}, {"x", "m"}, {"y", "m"}, {"z", "m"}});
  for (int eq = 0; eq < dofs.freeCount(); ++eq) {
    const NodeDof& d = dofs.dofOf(eq);
    const Eigen::Vector3d& x = model.nodes()[d.node];
    table.addRow({(long long)eq + 1, (long long)d.node, model.nameOf(d.node),
                  std::string(dofName(d.dof)), x.x(), x.y(), x.z()});
  }
  return table;
}

}  // namespace

std::vector<fs::path> exportMatrices(const Model& model, const fs::path& dir) {
  fs::create_directories(dir);
  std::vector<fs::path> written;
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);

  // 1. The matrices, as assembled (the same free-free blocks the analyses factorise).
  const auto save = [&](const SparseMatrix& A, const char* name) {
    writeMarket(A, dir / name);
    written.push_back(dir / name);
  };
  save(assembler.assemble(MatrixKind::stiffness), kStiffnessMtx);
  save(assembler.assemble(MatrixKind::mass), kMassMtx);
  const SparseMatrix G = assembler.assemble(MatrixKind::gyroscopic);
  if (G.coeffs().size() > 0 && G.coeffs().cwiseAbs().maxCoeff() > 0) save(G, kGyroscopicMtx);

  // 2. The right-hand side exactly as the static solver forms it (fem/static/LinearStatics).
  const Eigen::VectorXd f =
      reducedRightHandSide(model, dofs, loadVector(model, dofs), prescribedValues(model, dofs));
  writeMarket(f, dir / kLoadMtx);
  written.push_back(dir / kLoadMtx);

  // 3. What each row means.
  dofTable(model, dofs).write(dir / kDofsCsv);
  written.push_back(dir / kDofsCsv);
  return written;
}

}  // namespace beamrotor
