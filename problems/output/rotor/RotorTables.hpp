// The CSV tables of the rotor analyses: damped modes at one speed, the Campbell diagram and
// its critical speeds, and the unbalance response (the charts plot these).
#pragma once

#include <string>

#include "fem/rotor/RotorResults.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/run/RotorRunResult.hpp"

namespace beamrotor {

/// +1 forward, -1 backward, 0 planar: a whirl as a number a chart can colour by.
long long whirlSign(Whirl w);

/// Speed in rpm of a speed in rad/s.
double rpmOf(double speed);

/// A log decrement as a CSV cell: the number, or an empty cell where it is infinite (a real
/// eigenvalue: the damping ratio's sign tells a decaying mode from a growing one).
CsvCell logDecrementCell(double delta);

/// Plain journal and tilting-pad bearings: one row per bearing and table speed: bearing (name), bearing_index
/// (1, 2, ...), speed (rad/s), speed_rpm, eccentricity (e/c), attitude_angle (deg),
/// sommerfeld (mu Omega D L^3 / (8 W c^2)), kxx kxy kyx kyy (N/m), cxx cxy cyx cyy (N s/m) in
/// the bearing's axes as the deck writes them (x_b = global y).
CsvTable journalBearingsTable(const std::string& title,
                              const std::vector<JournalBearingCurve>& journals);

/// API 684: one row per response point and resonance peak: point, peak (1, 2, ... per point),
/// speed_rpm, amplitude (m), lower/upper_half_power_rpm (0: outside the sweep),
/// amplification_factor (0: unknown), amplification_method (half-power, modal-damping for
/// overlapping peaks, none), modal_damping_ratio (the zeta behind 1 / (2 zeta); 0 for
/// half-power), required_margin and actual_margin (%), pass (1 or 0).
CsvTable api684Table(const std::string& title, const UnbalanceOutcome& r);

/// Frequency response: one row per excitation frequency: frequency (Hz), omega (rad/s),
/// magnitude, phase (deg, unwrapped: UnwrappedPhase.hpp), real, imag of the receptance (m/N
/// for translations).
CsvTable frequencyResponseTable(const std::string& title, const FrequencyResponseResult& f);

/// One row per mode: mode, damped and natural frequency (Hz), damping ratio, log decrement
/// (empty for a real eigenvalue), whirl (forward, backward, planar) and whirl ratio.
CsvTable rotorModesTable(const std::string& title, const RotorModesResult& r);

/// One row per speed: speed (rad/s), speed_rpm, then per line l (from 1) line<l>_frequency
/// (damped, Hz), line<l>_damping_ratio, line<l>_log_decrement (empty for a real eigenvalue),
/// line<l>_whirl (+1, -1, 0) and line<l>_mac.
CsvTable campbellTable(const std::string& title, const CampbellResult& c);
/// Column names of campbellTable for line l (1-based).
std::string campbellColumn(int line, const std::string& what);
/// The number of lines a campbellTable holds.
int campbellLineCount(const CsvTable& campbell);

/// One row per critical speed: speed_rpm, speed (rad/s), frequency (Hz), line, damping
/// ratio, whirl (+1, -1, 0).
CsvTable criticalSpeedsTable(const std::string& title, const std::vector<CriticalSpeed>& c);

/// One row per speed: speed (rad/s), speed_rpm, then per response point P: P_amplitude (m,
/// orbit semi-major axis), P_uy_amplitude, P_uz_amplitude (m), P_uy_phase, P_uz_phase (deg,
/// of u = Re(U e^{i Omega t}), each unwrapped along the speeds: UnwrappedPhase.hpp).
CsvTable unbalanceTable(const std::string& title, const UnbalanceResult& u,
                        const std::vector<std::string>& points);

}  // namespace beamrotor
