// Looking at a drawn chart the way a reader would, in a test: is anything cut at the image's
// edge (the PNG), and do two pieces of text print over each other (the SVG gnuplot writes)?
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace beamrotor::test {

/// Ink (a pixel darker than light grey) within `band` pixels of a PNG's border, where nothing
/// of a chart belongs: text or a line that reaches the edge was cut there. One description
/// per edge touched ("left edge, rows 532 to 541"); empty when the border is clean.
std::vector<std::string> inkOnImageEdges(const std::filesystem::path& png, int band = 2);

/// Pairs of texts in a gnuplot SVG whose boxes overlap, texts reaching outside the canvas, and
/// numbers padded with zeros no reader needs (a tick label `1000.0000000`: three or more zeros
/// ending a decimal fraction). A text's box is estimated from below (half an em per character,
/// 0.6 em tall) so that what is reported certainly overlaps. One description per fault.
std::vector<std::string> textFaults(const std::filesystem::path& svg);

}  // namespace beamrotor::test
