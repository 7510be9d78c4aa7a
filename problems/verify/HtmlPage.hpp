// The verification report as one self-contained HTML page: the deck checks as tables, the
// charts inlined as SVG (no external files, scripts or styles), a sentence under each.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/verify/DeckChecks.hpp"

namespace beamrotor::verify {

/// A chart drawn into the report directory and the sentence under it.
struct ReportFigure {
  std::string title;
  std::string caption;
  std::filesystem::path svg;  ///< the drawn SVG, read and inlined; a note when missing
};

struct ReportContent {
  std::string generated;  ///< e.g. "beamrotor 0.1.0, 2026-11-22 20:10 UTC"
  std::vector<DeckChecks> decks;
  std::vector<ReportFigure> convergence;  ///< empty: a note on how to add them
  /// Decks without a convergence study and why (deck file, reason), e.g. nothing to refine.
  std::vector<std::pair<std::string, std::string>> notConverged;
  std::vector<ReportFigure> failures;
};

/// The SVG file's <svg> element, without the XML declaration and doctype before it.
std::string inlineSvg(const std::filesystem::path& svg);

/// The whole page.
std::string reportHtml(const ReportContent& content);

}  // namespace beamrotor::verify
