// The `train:` block (FORMAT.md, "Drive trains in torsion"): shaft lines of segments with
// their disks, couplings between stations and gear meshes joining two shafts.
#include <algorithm>

#include "problems/deck/Deck.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

void readShaft(const Context& c, const Field& f, TrainShaft& shaft, std::vector<std::string>& disks,
               std::vector<TrainDisk>& inertias) {
  f.allowOnly({"name", "segments", "disks", "stations"}, "a shaft");
  const Field segments = f.require("segments");
  double length = 0;
  for (const Field& sf : segments.items()) {
    sf.allowOnly({"length", "section", "elements", "size"}, "a shaft's segment");
    DeckSegment s;
    s.length = sf.require("length").positive(c.evaluator, dim::length);
    readSegmentMesh(c, sf, s);
    if (!(s.section->J > 0))
      sf.require("section").fail("a shaft twists, which needs the torsion constant: give section '" +
                                 s.sectionName + "' J");
    shaft.segments.push_back({s.length, s.section, s.elements, s.size, s.options});
    length += s.length;
  }
  if (shaft.segments.empty()) segments.fail("a shaft needs at least one segment");
  TakenNames names{"start", "end"};
  const auto station = [&](const Field& sf, const std::string& what) {
    const Field nf = sf.require("name");
    claimName(nf, nf.name(), names, "a station of shaft '" + shaft.name + "'");
    const Field at = sf.require("at");
    const double x = at.nonNegative(c.evaluator, dim::length);
    if (x > length * (1 + 1e-12))
      at.fail(what + " lies beyond the shaft's end (its segments are " + formatNumber(length) +
              " m long)");
    shaft.stations.push_back({nf.name(), std::min(x, length)});
  };
  if (auto list = f.get("stations"); list && !list->isNull())
    for (const Field& sf : list->items()) {
      sf.allowOnly({"name", "at"}, "a station");
      station(sf, "the station");
    }
  if (auto list = f.get("disks"); list && !list->isNull())
    for (const Field& df : list->items()) {
      df.allowOnly({"name", "at", "Jp"}, "a disk");
      station(df, "the disk");
      disks.push_back(shaft.name + "." + shaft.stations.back().name);
      inertias.push_back(
          {{shaft.name, shaft.stations.back().name}, df.require("Jp").positive(c.evaluator, dim::inertia)});
    }
}

}  // namespace

TrainStation trainStation(const Context& c, const Field& f) {
  const std::string text = f.name();
  const auto dot = text.find('.');
  const TrainSpec& train = c.deck.train;
  std::vector<std::string> all;
  for (const TrainShaft& s : train.shafts) {
    all.push_back(s.name + ".start");
    all.push_back(s.name + ".end");
    for (const NamedPoint& p : s.stations) all.push_back(s.name + "." + p.name);
  }
  if (dot != std::string::npos && std::find(all.begin(), all.end(), text) != all.end())
    return {text.substr(0, dot), text.substr(dot + 1)};
  f.fail("no station '" + text + "' in the train" + didYouMean(text, all) +
         " (a station is SHAFT.start, SHAFT.end or SHAFT.NAME of a disk or station)");
}

void readTrain(Context& c) {
  const auto block = c.root.get("train");
  if (!block || block->isNull()) return;
  block->allowOnly({"shafts", "couplings", "gears"}, "a train");
  TrainSpec& train = c.deck.train;
  TakenNames shaftNames, joints;
  std::vector<std::string> disks;
  for (const Field& f : block->require("shafts").items()) {
    TrainShaft shaft;
    const Field nf = f.require("name");
    shaft.name = nf.name();
    if (shaft.name.find('.') != std::string::npos)
      nf.fail("a shaft's name holds no '.' (stations are named SHAFT.NAME)");
    claimName(nf, shaft.name, shaftNames, "a shaft");
    readShaft(c, f, shaft, disks, train.disks);
    train.shafts.push_back(std::move(shaft));
  }
  if (train.shafts.empty()) block->require("shafts").fail("a train needs at least one shaft");
  const auto joint = [&](const Field& f, bool gear) {
    f.allowOnly(gear ? std::vector<std::string>{"name", "from", "to", "ratio", "stiffness",
                                                "damping"}
                     : std::vector<std::string>{"name", "from", "to", "stiffness", "damping"},
                gear ? "a gear mesh" : "a coupling");
    TrainJoint j;
    const Field nf = f.require("name");
    j.name = nf.name();
    claimName(nf, j.name, joints, "a coupling or gear");
    j.from = trainStation(c, f.require("from"));
    j.to = trainStation(c, f.require("to"));
    if (j.from.name() == j.to.name()) f.require("to").fail("a joint joins two different stations");
    j.stiffness = f.require("stiffness").positive(c.evaluator, dim::rotationalStiffness);
    if (auto d = f.get("damping")) j.damping = d->nonNegative(c.evaluator, dim::rotationalDamping);
    if (gear) j.ratio = f.require("ratio").positive(c.evaluator, dim::none);
    (gear ? train.gears : train.couplings).push_back(j);
  };
  if (auto list = block->get("couplings"); list && !list->isNull())
    for (const Field& f : list->items()) joint(f, false);
  if (auto list = block->get("gears"); list && !list->isNull())
    for (const Field& f : list->items()) joint(f, true);
  try {
    shaftSpeedRatios(train);
  } catch (const std::invalid_argument& e) {
    block->fail(e.what());
  }
}

}  // namespace beamrotor::reader
