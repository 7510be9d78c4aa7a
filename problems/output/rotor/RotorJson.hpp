// The results.json entries of the rotor analyses (layout in JsonWriter.hpp's terms):
//   rotor:      {type, name, speed_rpm, frequencies_hz (damped), modes [{mode, frequency_hz,
//                natural_frequency_hz, damping_ratio, log_decrement (null when infinite),
//                whirl, whirl_ratio, eigenvalue [re, im]}], time_s, files}
//   campbell:   {type, name, order, speeds_rpm, lines [{line, frequencies_hz, damping_ratio,
//                whirl, mac}], critical_speeds [{rpm, speed_rad_s, frequency_hz, line,
//                damping_ratio, whirl}], symbolic_analyses, time_s, files}
//   unbalance:  {type, name, speeds_rpm, response {POINT: {amplitude_m, uy_amplitude_m,
//                uz_amplitude_m, uy_phase_deg, uz_phase_deg (unwrapped along the speeds),
//                peak {amplitude_m, rpm}}},
//                time_s, files}
//   rigid-body: {type, name, rigid_body {mass, com_x, J_com, Jp, bearing_x {A, B},
//                stiffness {A, B}}, two_dof {a, b, d, rho2, decoupled, modes [{mode,
//                frequency_hz, k_rad_s, kind, z, phi, n (null when infinite), FA, FB,
//                inertia_force, inertia_moment}]}}
//   critical-speed-map: {type, name, whirl ("non-rotating (gyroscopic moments neglected)"),
//                stiffness [N/m], critical_speeds_rpm [[per stiffness, ascending]],
//                pinned_rpm, free_free_rpm,
//                bearings [{bearing, speeds_rpm, kxx, kyy}], time_s, files}
//   bearing-loads: {type, name, bearing_support (rigid | elastic), weight [x, y, z] (N),
//                bearings {NAME: {x, fy, fz, load}} (N, the force on the shaft; load its
//                magnitude), largest_sag {x, uy, uz, magnitude} (m, over the nodes), time_s, files}
#pragma once

#include "problems/output/JsonWriter.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// The entry of one solved rotor analysis, by its kind's result (a's own).
Json rotorJson(const AnalysisOutcome& a, const RotorModesResult& r);
Json rotorJson(const AnalysisOutcome& a, const CampbellOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const UnbalanceOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const RigidBodyOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const FrequencyResponseOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const CriticalSpeedMapOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const BearingLoadsOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const LevelOneOutcome& r);
Json rotorJson(const AnalysisOutcome& a, const RunUpOutcome& r);

}  // namespace beamrotor
