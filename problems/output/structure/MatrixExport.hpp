// Matrix Market export of a model's free-free system, for users who want to solve it with
// other tools (SciPy, MATLAB, Julia): K u = f with the supports eliminated exactly as the
// static solver does, M for K x = omega^2 M x, and, for a spinning model, G per unit speed.
#pragma once

#include <filesystem>
#include <vector>

#include "fem/model/Model.hpp"

namespace beamrotor {

inline constexpr const char* kStiffnessMtx = "K.mtx";
inline constexpr const char* kMassMtx = "M.mtx";
inline constexpr const char* kGyroscopicMtx = "G.mtx";
inline constexpr const char* kLoadMtx = "f.mtx";
inline constexpr const char* kDofsCsv = "dofs.csv";

/// Writes into dir (created if needed, files of the same names replaced):
///   K.mtx, M.mtx  free-free stiffness (N/m, N, N m/rad) and mass (kg, kg m^2), coordinate
///                 format, every stored entry of the assembled matrices (structural zeros too);
///   G.mtx         gyroscopic matrix per unit spin speed (kg m^2), only when it is not zero;
///   f.mtx         f_F - K_FC u_C, the right-hand side with prescribed supports moved over;
///   dofs.csv      row (1-based, as in the .mtx files) -> node, point name, dof, x, y, z.
/// Rows are the DofMap's free equations. Throws std::runtime_error when a file cannot be
/// written. Returns the files written.
std::vector<std::filesystem::path> exportMatrices(const Model& model,
                                                  const std::filesystem::path& dir);

}  // namespace beamrotor
