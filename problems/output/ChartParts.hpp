// Pieces every gnuplot chart shares (Charts.cpp, RotorCharts.cpp): the line colours, number
// formatting and the multi-panel layout.
#pragma once

#include <cstddef>
#include <string>

namespace beamrotor {

/// "linecolor rgb '#...'": the i-th colour of the chart palette (cycling).
std::string colour(std::size_t i);
/// The i-th palette colour as a gnuplot integer constant (0xRRGGBB), for `lc rgb variable`.
std::string colourValue(std::size_t i);

/// x with 6 significant digits, as gnuplot reads it.
std::string number(double x);

/// A caption of one or more lines (separated by '\n') as a gnuplot string expression.
std::string captionText(const std::string& caption);

/// `set multiplot` for a grid of panels under a caption. gnuplot takes the margins as
/// fractions of the canvas; they are set here in pixels so that labels fit whatever the
/// chart's size.
std::string panelLayout(int rows, int columns, const std::string& caption, int width, int height,
                        int rightMargin = 30);

}  // namespace beamrotor
