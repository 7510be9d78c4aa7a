#include "problems/output/MatrixExport.hpp"

#include <stdexcept>
#include <unsupported/Eigen/SparseExtra>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "problems/output/CsvTable.hpp"

namespace beamrotor {

namespace fs = std::filesystem;

namespace {

void requireWritten(bool ok, const fs::path& file) {
  if (!ok) throw std::runtime_error("cannot write " + file.string());
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
    requireWritten(Eigen::saveMarket(A, (dir / name).string()), dir / name);
    written.push_back(dir / name);
  };
  save(assembler.assemble(MatrixKind::stiffness), kStiffnessMtx);
  save(assembler.assemble(MatrixKind::mass), kMassMtx);
  const SparseMatrix G = assembler.assemble(MatrixKind::gyroscopic);
  if (G.coeffs().size() > 0 && G.coeffs().cwiseAbs().maxCoeff() > 0) save(G, kGyroscopicMtx);

  // 2. The right-hand side exactly as the static solver forms it (fem/static/LinearStatics).
  const Eigen::VectorXd f =
      reducedRightHandSide(model, dofs, loadVector(model, dofs), prescribedValues(model, dofs));
  requireWritten(Eigen::saveMarketVector(f, (dir / kLoadMtx).string()), dir / kLoadMtx);
  written.push_back(dir / kLoadMtx);

  // 3. What each row means.
  dofTable(model, dofs).write(dir / kDofsCsv);
  written.push_back(dir / kDofsCsv);
  return written;
}

}  // namespace beamrotor
