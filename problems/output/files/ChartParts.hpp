// Pieces every gnuplot chart shares (Charts.cpp, RotorCharts.cpp): the line colours, number
// formatting and the multi-panel layout.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace beamrotor {

/// "linecolor rgb '#...'": the i-th colour of the chart palette (cycling).
std::string colour(std::size_t i);
/// "linecolor rgb '#...' dashtype n": the i-th curve's colour and dash together. The first
/// ten curves differ in colour, any two of the first distinctLineStyles() in the pair, and
/// neighbours always in both (so curves read apart in grey print too).
std::string lineStyle(std::size_t i);
/// How many curves lineStyle keeps apart.
std::size_t distinctLineStyles();
/// The i-th palette colour as a gnuplot integer constant (0xRRGGBB), for `lc rgb variable`.
std::string colourValue(std::size_t i);

/// x with 6 significant digits, as gnuplot reads it.
std::string number(double x);

/// x as a label or title shows a value to a reader: 4 significant digits, and "0" for a zero
/// of either sign or a value within round-off of `scale` (1e-9 of it: a resultant that is zero
/// but for the solve's round-off, not 2.274e-16).
std::string labelNumber(double x, double scale = 0);

/// A caption of one or more lines (separated by '\n') as a gnuplot string expression.
std::string captionText(const std::string& caption);

/// Commands that make `axis` ("x", "y", "y2") logarithmic over data from low to high (both
/// > 0): the range widened to whole decades, so that every major tick is a power of ten and
/// reads 10^n (never a long decimal), with a tick every one, two, ... decades so that at most
/// about eight are labelled, and minor ticks between. Data that is not positive and finite
/// gets the plain log scale with labels in %g.
std::string logAxis(const std::string& axis, double low, double high);

/// The smallest and largest positive finite values given to include() (both 0 before any):
/// what a log axis can draw.
struct PositiveRange {
  double low = 0, high = 0;
  void include(double v);
};
/// logAxis over a PositiveRange.
std::string logAxis(const std::string& axis, const PositiveRange& range);

/// Pixels of canvas a key outside the plot needs for these titles (sample line, gap and the
/// longest title at the 12 pt default font), so that no entry is cut at the image's edge.
int keyWidth(const std::vector<std::string>& titles);

/// Estimated width in pixels of text at the default 12 pt font (an upper bound for gnuplot's
/// sans-serif: digits and most letters are narrower).
int textWidth(const std::string& text);

/// `set multiplot` for a grid of panels under a caption. gnuplot takes the margins as
/// fractions of the canvas; they are set here in pixels so that labels fit whatever the
/// chart's size; y tick labels are compact (%g) to fit the left margin.
std::string panelLayout(int rows, int columns, const std::string& caption, int width, int height,
                        int rightMargin = 30);

/// `set multiplot` for a grid of 3d views under a caption, with gnuplot's own margins: screen
/// margins (panelLayout's) make gnuplot fit the view's unit box to them whatever `set view`'s
/// scale, and the projected box of a 3d view is about 1.5 times that box, so it would spill
/// off its panel; with its own margins the view's box spans 8/7 of the panel at scale 1.
std::string viewLayout(int rows, int columns, const std::string& caption);

}  // namespace beamrotor
