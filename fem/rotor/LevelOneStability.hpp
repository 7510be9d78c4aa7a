// API 684 Level I stability screening of a compressor rotor at its rated speed: how much
// aerodynamic cross-coupling the rotor-bearing system can take before a mode loses all its
// damping (Q0), against how much the stages are anticipated to produce (Qa).
//
// Qa: API 617's estimate of the cross-coupling of the stages (API 617, 7th ed. 2002, 2.6.5;
// 8th ed. 2014, the Level I analysis; also API RP 684, 2nd ed. 2005, sec. 2.10),
//   Qa = sum over stages of  B_c C P_r / (D_c H_c N) * (rho_d / rho_s),
// B_c = 3 (centrifugal stages), P_r the stage's rated power, D_c the impeller diameter, H_c the
// restrictive tip width (the smaller of the impeller's discharge width and the diffuser's),
// N the speed, rho_d / rho_s the stage's discharge over suction density. C P_r / N is the
// stage torque P_r / Omega (C = 60 / (2 pi) = 9.549 turns P / N into torque for N in rpm), so in
// SI units here
//   Qa = sum  B_c (P_r / Omega) / (D_c H_c) * (rho_d / rho_s)     (N/m; W, rad/s, m).
// API's metric form, C = 9.55 with P_r in kW, N in rpm and D_c, H_c in mm, gives the torque in
// kN m over mm^2: its number is Qa in units of 1e9 N/m (MN/mm).
//
// Q0: cross-coupled stiffness k_yz = +Q, k_zy = -Q added at one station (the stages' centre,
// mid-span by default) until the least log decrement of the modes at the rated speed is zero.
// With tilting pads kept as dofs (elements/TiltingPadFilm.hpp) the modes are the full model's
// (each at its own frequency, nothing condensed) and the pads' own modes are looked at beside
// the rotor's `modes`: one of them is the least damped only when its log decrement is the least.
// The least stable mode's growth rate Re(lambda) / |lambda| (RotorStability.hpp) is continuous
// in Q; it is negative at Q = 0 for a stable rotor and grows with Q, so a bracket [0, Q_hi],
// Q_hi doubled from Qa until the rotor grows, holds the root, which regula falsi (Illinois,
// SpeedRoot.hpp) narrows to a relative tolerance.
//
// Verdict (API 617 7th ed. sec. 2.6.5, Level I screening criteria, as API RP 684 sec. 2.10
// explains them; paragraph numbers differ between editions): a Level II
// analysis is required when the log decrement with Qa added is below 0.1, or Q0 / Qa < 2; with
// 2 <= Q0 / Qa < 10 it is also required if the machine lies in region B of API's map of the
// critical speed ratio against the average gas density (below). Level I passes otherwise.
//
// The map (API 617 7th ed. fig. 2-7; its boundary as digitised in ROSS, ross/report.py): the
// critical speed ratio CSR = maximum continuous speed / first critical speed on rigid supports
// against the average gas density rho (kg/m^3). Region B, above the boundary
//   CSR_B = 2.5                    for rho <= 16.53,
//   CSR_B = 2.69 - 0.0115 rho      for 16.53 < rho <= 60   (2.0 at 60),
// and every machine with rho > 60 kg/m^3 (3.75 lbm/ft^3); region A below.
#pragma once

#include <optional>
#include <vector>

#include "fem/rotor/RotorModes.hpp"
#include "fem/rotor/SpeedRoot.hpp"

namespace beamrotor {

/// One compressor stage as API 617's Qa formula reads it (SI units).
struct CompressorStage {
  double power = 0;             ///< W, rated power of the stage
  double diameter = 0;          ///< m, impeller diameter D_c
  double tipWidth = 0;          ///< m, restrictive tip width H_c
  double dischargeDensity = 0;  ///< kg/m^3, rho_d
  double suctionDensity = 0;    ///< kg/m^3, rho_s
};

/// API 617's B_c for centrifugal stages.
inline constexpr double kCentrifugalStageFactor = 3;
/// API 684's least log decrement at Qa for Level I to pass.
inline constexpr double kLevelOneLogDecrement = 0.1;
/// Q0 / Qa below which Level II is required; below kLevelOneRegionRatio the CSR map decides.
inline constexpr double kLevelOneMinimumRatio = 2, kLevelOneRegionRatio = 10;

/// Qa (N/m) of the stages at spin speed Omega (rad/s). Throws std::invalid_argument for a
/// speed, diameter, width or density that is not > 0, or a power < 0.
double anticipatedCrossCoupling(const std::vector<CompressorStage>& stages, double speed);

/// Where the machine lies on API 617's map of the critical speed ratio against the average gas
/// density.
struct CriticalSpeedRatioPoint {
  double maximumContinuousSpeed = 0;  ///< rad/s
  double rigidCriticalSpeed = 0;      ///< rad/s, first critical speed on rigid supports
  double averageDensity = 0;          ///< kg/m^3
  double ratio = 0;                   ///< CSR = maximumContinuousSpeed / rigidCriticalSpeed
  double boundary = 0;                ///< CSR_B at averageDensity (0 above 60 kg/m^3)
  bool regionB = false;               ///< ratio > boundary
};

/// Where the least log decrement against added cross-coupling was sampled (for a chart).
struct CrossCouplingSample {
  double crossCoupling = 0;  ///< N/m
  double logDecrement = 0;   ///< least log decrement of the modes
};

struct LevelOneResult {
  double speed = 0;                ///< rad/s
  int node = -1;                   ///< station of the added cross-coupling
  double anticipated = 0;          ///< Qa, N/m
  double baseLogDecrement = 0;     ///< least log decrement without added cross-coupling
  double logDecrementAtQa = 0;     ///< least log decrement with Qa added
  double frequencyHzAtQa = 0;      ///< damped frequency of that mode
  bool bearingModeAtQa = false;    ///< that mode is a bearing's own (a pad's tilt)
  /// Q0 (N/m): where the least log decrement is zero; 0 when the rotor is not stable without
  /// added cross-coupling. Unset when no Q up to 2^40 Qa destabilises it (found = false).
  double zeroDecrement = 0;
  bool found = false;
  double frequencyHzAtQ0 = 0;      ///< damped frequency of the mode that loses its damping
  Whirl whirlAtQ0 = Whirl::planar;
  bool bearingModeAtQ0 = false;    ///< that mode is a bearing's own (a pad's tilt)
  int evaluations = 0;             ///< eigen-solutions spent on Q0
  double ratio = 0;                ///< Q0 / Qa (infinite when not found)
  /// 2 <= Q0/Qa < 10: API's CSR/density map decides (region B fails)
  bool mapDecides = false;
  /// log decrement at Qa >= 0.1, Q0 / Qa >= 2 and, where the map decides, region A
  bool pass = false;
  std::vector<CrossCouplingSample> curve;  ///< ascending Q from 0, for the chart
  CriticalSpeedRatioPoint map;  ///< the machine on API 617's CSR map
};

/// API 617's boundary CSR_B between regions A and B at average gas density rho (kg/m^3, >= 0):
/// 0 above 60 kg/m^3, where the whole map is region B.
double criticalSpeedRatioBoundary(double averageDensity);

/// The machine's point on the map. Throws std::invalid_argument unless both speeds are > 0
/// and the density >= 0.
CriticalSpeedRatioPoint criticalSpeedRatioPoint(double maximumContinuousSpeed,
                                                double rigidCriticalSpeed, double averageDensity);

/// API's average gas density of a compressor: the mean of the first stage's suction and the
/// last stage's discharge density (kg/m^3). Throws std::invalid_argument for no stages.
double averageGasDensity(const std::vector<CompressorStage>& stages);

/// The screening of `model` at spin speed Omega (rad/s) with the modes `options` asks for,
/// cross-coupling added at `node`, Qa = `anticipated` > 0 (N/m), the machine's point `map` on
/// API's CSR map; Q0 to the relative `tolerance`; `samples` + 1 equal steps of Q over
/// [0, max(1.5 Q0, 1.5 Qa)] for the curve. Throws SolveError when an eigen-solution fails,
/// std::invalid_argument for Qa <= 0 or a node without free uy, uz.
LevelOneResult levelOneStability(const Model& model, const RotorOptions& options, int node,
                                 double speed, double anticipated,
                                 const CriticalSpeedRatioPoint& map,
                                 double tolerance = kSpeedTolerance, int samples = 40);

}  // namespace beamrotor
