// The envelope of a member's stress resultants over the load combinations, as a chart: one
// panel per resultant the frame carries, the band between its largest and smallest value
// along the member, each extreme marked with the combination that governs it.
#pragma once

#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

/// Frames of at most this many members chart each member's envelope on its own (with more, the
/// envelope drawn on the frame, frameEnvelopeChart, and the envelope tables remain).
inline constexpr std::size_t kEnvelopeChartsUpTo = 12;

/// `<stem>_envelope_<member>`: the chart of one member's envelope.
std::string envelopeChart(const std::string& stem, const std::string& member);

/// The envelope of memberEnvelopeTable `table`, written to csvFile: panels for the resultants
/// that are not zero along the whole member (N, Vy, Mz in a planar frame), in kN and kN m
/// against the distance s (m) from the member's start; or in the user's `units` where set
/// (the table then holds them).
ChartScript memberEnvelopeChart(const std::string& caption, const std::string& chartName,
                                const CsvTable& table, const std::string& csvFile,
                                const OutputUnits& units = {});

}  // namespace beamrotor
