#include "problems/verify/Report.hpp"

#include <algorithm>
#include <ctime>

#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/ChartBatch.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/verify/HtmlPage.hpp"

namespace beamrotor::verify {

namespace {

namespace fs = std::filesystem;

/// Hook for the convergence study (`beamrotor converge`, another branch): every SVG chart
/// under DIR/convergence/, sorted, titled by its path, e.g. "cantilever/error_vs_dofs".
std::vector<ReportFigure> convergenceFigures(const fs::path& dir) {
  std::vector<ReportFigure> figures;
  if (!fs::is_directory(dir)) return figures;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".svg") {
      const fs::path relative = fs::relative(entry.path(), dir).replace_extension();
      figures.push_back({"Convergence: " + relative.generic_string(),
                         "Error against cost for each method, as written by beamrotor converge "
                         "(see convergence.json beside it for the numbers).",
                         entry.path()});
    }
  std::sort(figures.begin(), figures.end(),
            [](const ReportFigure& a, const ReportFigure& b) { return a.svg < b.svg; });
  return figures;
}

std::string generatedLine() {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M", std::gmtime(&now));
  return std::string("beamrotor ") + BEAMROTOR_VERSION + ", generated " + stamp + " UTC";
}

}  // namespace

ReportSummary writeReport(const ReportOptions& options, std::ostream& log) {
  // 0. What it needs, before any work: the shipped decks, and a directory it may write.
  std::error_code ec;
  const std::vector<fs::path> decks = fs::is_directory(options.problemsDir, ec)
                                          ? decksIn(options.problemsDir)
                                          : std::vector<fs::path>{};
  if (decks.empty())
    throw std::invalid_argument(
        "the report checks the shipped decks (problems/*.yaml of the beamrotor source tree), but "
        "'" +
        options.problemsDir.string() +
        "' holds none: run it from the source directory, or give --decks DIR");
  const fs::path charts = options.outDir / "charts";
  const fs::path page = options.outDir / "index.html";
  if (fs::exists(fs::symlink_status(page, ec)) &&
      !fs::exists(fs::symlink_status(charts / kMarkerFile, ec)))
    throw std::invalid_argument("refusing to replace '" + page.string() +
                                "': it is not a report beamrotor wrote (no charts/" + kMarkerFile +
                                " beside it); choose another output directory with --out DIR");
  ReportContent content;
  content.generated = generatedLine();
  // 1. The decks' checks.
  log << "checking the decks in " << options.problemsDir.string() << "\n";
  content.decks = runDeckChecks(decks);
  ReportSummary summary;
  for (const DeckChecks& d : content.decks) {
    log << "  " << d.deck << (d.error.empty() ? "" : ": not solved") << "\n";
    summary.unsolvedDecks += !d.error.empty();
    summary.notApplied += int(d.notApplied.size());
    for (const auto& entry : d.checks) {
      ++summary.checks;
      summary.failedChecks += !entry.second.pass();
    }
  }
  // 2. The failure-case studies, drawn into DIR/charts (replaced as a whole).
  log << "running the failure-case studies\n";
  const std::vector<StudyChart> studies = failureCharts(options.failures);
  writeDirectoryAtomically(charts, [&](const fs::path& temporary) {
    ChartBatch drawn(ChartFormat::both);  // SVG, which the page inlines, and PNG; drawn together
    for (const StudyChart& chart : studies) writeStudyChart(temporary, chart);
    drawn.draw();
  });
  for (const StudyChart& chart : studies)
    content.failures.push_back({chart.title, chart.caption, charts / (chart.name + ".svg")});
  // 3. The convergence charts, when a converge run left them.
  content.convergence = convergenceFigures(options.outDir / "convergence");
  content.notConverged = options.notConverged;
  // 4. The page.
  summary.page = page;
  const std::string html = reportHtml(content);
  writeFileAtomically(summary.page, [&](std::ostream& page) { page << html; });
  return summary;
}

}  // namespace beamrotor::verify
