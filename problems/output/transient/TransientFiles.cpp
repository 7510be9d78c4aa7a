#include "problems/output/transient/TransientFiles.hpp"

#include "problems/output/structure/Charts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/structure/VtkWriter.hpp"

namespace beamrotor {

CsvTable historyTable(const std::string& title, const TransientOutcome& transient) {
  std::vector<CsvColumn> columns{{"t", "s"}};
  for (const NamedHistory& h : transient.histories) columns.push_back({h.name, h.unit});
  CsvTable table(title, columns);
  const std::vector<double>& times = transient.result.times;
  for (std::size_t i = 0; i < times.size(); ++i) {
    std::vector<CsvCell> row{times[i]};
    // In place: moving a variant that may hold a string draws a false -Wmaybe-uninitialized
    // from GCC 12 in some unity batches.
    for (const NamedHistory& h : transient.histories)
      row.emplace_back(std::in_place_type<double>, h.values.at(i));
    table.addRow(std::move(row));
  }
  return table;
}

void writeTransientFiles(const std::filesystem::path& dir, const Model& model,
                         const std::string& stem, const TransientOutcome& transient,
                         const CsvTable& history, const std::string& caption) {
  history.write(dir / historyCsv(stem));
  if (!caption.empty() && !transient.histories.empty() && history.rowCount() > 1)
    drawChart(dir, historyChart(caption, historyChart(stem), history, historyCsv(stem)));
  const std::vector<Frame>& frames = transient.result.frames;
  if (frames.empty()) return;
  std::vector<PvdEntry> entries;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string file = frameVtu(stem, int(i) + 1);
    writeFrameVtu(dir / file, model, frames[i]);
    entries.push_back({frames[i].time, file});
  }
  writePvd(dir / collectionPvd(stem), entries);
}

}  // namespace beamrotor
