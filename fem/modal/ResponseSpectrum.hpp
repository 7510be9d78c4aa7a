// Response-spectrum analysis: the peak response of a supported structure to a ground
// acceleration given by its response spectrum, from the undamped modes. Mode j excited along
// global direction d moves as phi_j Gamma_jd Sa(T_j) / w_j^2 (Gamma_jd = r_d' M phi_j, the
// signed participation factor, phi_j mass-normalised); every output quantity (displacement,
// reaction, named element force, section force at each station, base force) is computed in each
// mode from that motion and the modal values combined (SRSS or CQC), never recovered from
// combined displacements; then the directions are combined (100/30 % or SRSS).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fem/assembly/Recovery.hpp"
#include "fem/modal/DesignSpectrum.hpp"
#include "fem/modal/ModalCombination.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

struct ResponseSpectrumOptions {
  int modes = 12;
  double shift = 0;            ///< rad^2/s^2, as for a modal analysis
  double dampingRatio = 0.05;  ///< of every mode, for CQC's correlations
  ModalRule rule = ModalRule::cqc;
  DirectionalRule directional = DirectionalRule::percent30;
  std::vector<int> directions{0};  ///< the excited global directions: 0 x, 1 y, 2 z
  int stationsPerElement = 4;      ///< section forces at this many + 1 stations per element
  /// When set, the spectrum of direction `vertical` (the others take the analysis' own).
  std::optional<DesignSpectrum> verticalSpectrum;
  int vertical = 1;
};

/// Peak values (magnitudes, >= 0) of every output quantity.
struct PeakResponse {
  NodalField displacement;                       ///< relative to the ground (m, rad)
  std::vector<ReactionComponent> reactions;      ///< every constrained dof, in support order
  std::vector<ReactionComponent> elementForces;  ///< named springs and bearings
  std::vector<BeamStation> stations;  ///< displacements and forces; stress and shear left 0
  std::array<double, 3> baseForce{};  ///< the total force into the ground along x, y, z (N)
};

/// One combination of the directions' peaks (ModalCombination.hpp's directionalFactors):
/// "x + 0.3 y + 0.3 z", or "SRSS".
struct DirectionalCombination {
  std::string name;
  std::vector<double> factors;  ///< per direction, in the result's directions' order
  PeakResponse peak;
};

struct ResponseSpectrumResult {
  ModalResult modal;
  std::vector<double> spectralAcceleration;  ///< Sa (m/s^2) at each mode's period
  Eigen::MatrixXd correlation;               ///< rho_ij between the modes' responses
  std::vector<int> directions;               ///< as in the options
  std::vector<PeakResponse> perDirection;    ///< each direction alone, modes combined
  /// Each combination of the directions (one when there is one direction).
  std::vector<DirectionalCombination> combinations;
  PeakResponse combined;  ///< the directions combined: per quantity the largest combination
  DesignSpectrum spectrum;                   ///< the spectrum read
  /// The vertical direction's own spectrum, when given, and each mode's Sa on it (m/s^2).
  std::optional<DesignSpectrum> verticalSpectrum;
  std::vector<double> verticalAcceleration;
  int vertical = 1;
  double dampingRatio = 0.05;
  ModalRule rule = ModalRule::cqc;
  DirectionalRule directional = DirectionalRule::percent30;
  std::vector<std::string> warnings;  ///< e.g. less than 90 % of the mass captured

  /// Sum of the modes' effective masses over the total mass along x, y, z (0 where no mass).
  std::array<double, 3> capturedFraction() const;
  /// Sa of mode j along direction d (m/s^2): the vertical spectrum's along the vertical.
  double saOf(std::size_t j, int d) const;
};

/// Solves the modes of `model` and its peak response to `spectrum` along each of the options'
/// directions. Throws std::invalid_argument for a direction carrying no mass, and
/// std::domain_error for a mode at zero frequency (a structure free to move with the ground).
/// A mode outside a spectrum table reads its nearer end value, with a warning.
ResponseSpectrumResult solveResponseSpectrum(const Model& model, const DesignSpectrum& spectrum,
                                             const ResponseSpectrumOptions& options);

/// The name of global direction d (0, 1, 2): "x", "y", "z".
const char* directionName(int d);

}  // namespace beamrotor
