// A torsion analysis, solved: the model in twist alone (the shaft line's, or the train's) and
// its modes; for a train also where excitation orders cross the natural frequencies over its
// speed range, and its steady response to harmonic torques at the operating speed and over
// that range. The model is its own (one dof per node, rx), so writers draw the shapes on it.
#pragma once

#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/deck/torsion/TorsionKind.hpp"

namespace beamrotor {

/// Where an excitation order meets a natural frequency: order x speed = frequency.
struct TorsionCrossing {
  double order = 0;        ///< of the reference shaft's speed
  int mode = 0;            ///< 1-based, as the modes
  double frequencyHz = 0;
  double speed = 0;        ///< rad/s of the reference shaft
};

/// One quantity of the steady response: its complex amplitude at each excitation order and
/// the peak of its sum over a revolution.
struct ResponseTrace {
  std::string name;
  std::vector<std::complex<double>> amplitudes;  ///< per TorsionResponse::orders
  double peak = 0;
};

/// The steady response at one speed: the torques in the couplings, the gear meshes (on the
/// pinion's side) and along each shaft (its largest), and the twist of every named station.
struct TorsionResponse {
  double speed = 0;            ///< rad/s of the reference shaft
  std::vector<double> orders;  ///< the excitation frequencies as orders of that speed
  std::vector<ResponseTrace> torques;  ///< N m: couplings, gears, then shafts
  std::vector<ResponseTrace> twists;   ///< rad: every station SHAFT.NAME
};

struct TorsionOutcome {
  std::shared_ptr<const Model> model;  ///< the line or train in twist: rx at every node
  ModalResult modes;
  bool free = false;  ///< no support holds the twist: the first mode is the train's rotation
  // A train's only:
  std::vector<std::string> shafts;  ///< their names
  std::vector<double> speedRatios;  ///< each shaft's speed over the reference shaft's
  std::string reference;            ///< the shaft whose speed the speeds and orders are in
  std::vector<double> orders;       ///< of the interference diagram
  double speedFrom = 0, speedTo = 0;  ///< its range (rad/s); equal when none
  std::vector<TorsionCrossing> crossings;  ///< in the range, by speed
  std::vector<HarmonicTorque> excitation;  ///< the harmonic torques, as given or from a crank
  std::optional<TorsionResponse> atSpeed;  ///< at the operating speed
  std::vector<TorsionResponse> sweep;      ///< over the speed range
};

/// The peak over a revolution of sum_j Re(a_j exp(i o_j theta)) in absolute value, for one set
/// of orders o_j > 0 and any amplitudes. Exact for one order (|a|); otherwise the largest of 64
/// samples per period of the highest order over two revolutions (so half orders repeat),
/// refined by golden-section search. The samples' phasors exp(i o_j theta_k) are computed once
/// for the orders, so the peaks of many quantities at one speed share them.
class HarmonicPeak {
 public:
  explicit HarmonicPeak(std::vector<double> orders);
  double operator()(const std::vector<std::complex<double>>& amplitudes) const;

 private:
  double valueAt(const std::vector<std::complex<double>>& amplitudes, double theta) const;
  std::vector<double> orders_;
  int samples_ = 0;
  double step_ = 0;
  std::vector<std::complex<double>> phasors_;  ///< [sample][order]
};

/// What a check quantity `torsion torque|twist NAME` reads: the trace at the operating speed.
double measureTorsion(const std::string& property, const std::string& target,
                      const TorsionOutcome& t);

}  // namespace beamrotor
