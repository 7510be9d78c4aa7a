#include "problems/output/structure/StabilityOutput.hpp"

#include <algorithm>
#include <cmath>

#include "fem/modal/RigidMotion.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/structure/Charts.hpp"
#include "problems/output/structure/FrameCharts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/structure/VtkWriter.hpp"

namespace beamrotor {

namespace {

/// Every buckling mode in file order: the positive factors, then the reversed ones.
std::vector<const BucklingMode*> allModes(const BucklingResult& r) {
  std::vector<const BucklingMode*> out;
  for (const BucklingMode& m : r.modes) out.push_back(&m);
  for (const BucklingMode& m : r.reversed) out.push_back(&m);
  return out;
}

}  // namespace

CsvTable bucklingFactorsTable(const std::string& title, const BucklingResult& r) {
  CsvTable t(title, {{"mode", ""}, {"load_factor", ""}, {"reversed", ""}});
  const auto modes = allModes(r);
  for (std::size_t i = 0; i < modes.size(); ++i)
    t.addRow({(long long)(i + 1), modes[i]->factor, (long long)(modes[i]->factor < 0)});
  return t;
}

ModalResult bucklingShapes(const Model& model, const BucklingResult& r) {
  ModalResult out;
  for (const BucklingMode* b : allModes(r)) {
    Mode m;
    m.shape = b->shape;
    m.description = "load factor " + number(b->factor) + (b->factor < 0 ? " (load reversed)" : "");
    if (!model.members().empty())
      m.description += ", " + describeRigidMotion(rigidMotionShares(model, b->shape), "motion");
    out.modes.push_back(std::move(m));
  }
  return out;
}

Json bucklingJson(const AnalysisOutcome& a) {
  const BucklingResult& r = *resultOf<BucklingResult>(a);
  const std::string stem = fileStem(a.name);
  Json out = {{"type", a.type}, {"name", a.name}};
  Json factors = Json::array(), reversed = Json::array(), modes = Json::array(),
       vtus = Json::array();
  const auto all = allModes(r);
  for (std::size_t i = 0; i < all.size(); ++i) {
    (all[i]->factor > 0 ? factors : reversed).push_back(all[i]->factor);
    modes.push_back({{"mode", i + 1}, {"load_factor", all[i]->factor}});
    vtus.push_back(modeVtu(stem, int(i) + 1));
  }
  out["load_factors"] = factors;
  out["reversed_load_factors"] = reversed;
  out["modes"] = modes;
  out["reference"] = {{"reactions", reactionsJson(r.reference)}};
  out["time_s"] = r.time.total;
  out["files"] = {{"factors_csv", bucklingFactorsCsv(stem)},
                  {"shapes_csv", shapesCsv(stem)},
                  {"pvd", collectionPvd(stem)},
                  {"vtu", vtus}};
  return out;
}

Json secondOrderJson(const SecondOrderResult& r) {
  Json out = Json::object();
  // No compression: no critical load (null rather than an infinite number).
  if (std::isfinite(r.criticalFactor))
    out["critical_factor"] = r.criticalFactor;
  else
    out["critical_factor"] = nullptr;
  out["displacement_amplification"] = r.displacementAmplification;
  out["rotation_amplification"] = r.rotationAmplification;
  out["moment_amplification"] = r.momentAmplification;
  out["stress_amplification"] = r.stressAmplification;
  out["iterations"] = r.iterations;
  out["first_order"] = {{"max_translation", r.firstOrderTranslation},
                        {"max_rotation", r.firstOrderRotation}};
  out["first_order"]["reactions"] = reactionsJson(r.firstOrder);
  return out;
}

void writeBucklingFiles(const PreparedAnalysis& p, const Model& model,
                        const std::filesystem::path& dir, const std::string& caption, bool charts,
                        bool planar, const OutputUnits& units) {
  const BucklingResult& r = *resultOf<BucklingResult>(*p.outcome);
  p.modes->write(dir / bucklingFactorsCsv(p.stem));
  p.shapes->write(dir / shapesCsv(p.stem));
  const auto all = allModes(r);
  std::vector<PvdEntry> entries;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const int n = int(i) + 1;
    writeShapeVtu(dir / modeVtu(p.stem, n), model, all[i]->shape, n, "load_factor",
                  all[i]->factor);
    entries.push_back({double(n), modeVtu(p.stem, n)});
  }
  writePvd(dir / collectionPvd(p.stem), entries);
  if (!charts || p.shapes->rowCount() == 0) return;
  const ModalResult shapes = bucklingShapes(model, r);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < shapes.modes.size(); ++i)
    labels.push_back(model.members().empty() ? shapes.modes[i].description
                                             : "mode " + std::to_string(i + 1) + ": " +
                                                   shapes.modes[i].description);
  if (!model.members().empty()) {
    drawChart(dir, frameShapesChart(caption, shapesChart(p.stem), model, shapes.modes, labels,
                                    planar, units));
    return;
  }
  labels.resize(std::min<std::size_t>(4, labels.size()));
  drawChart(dir, labelledShapesChart(caption, shapesChart(p.stem), model, shapes.modes, labels,
                                     *p.shapes, shapesCsv(p.stem), units));
}

}  // namespace beamrotor
