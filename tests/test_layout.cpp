// The layout docs/layout.md promises, kept true: includes run one way only (elements -> fem,
// meshes -> fem and elements, problems -> all; inside fem/ and problems/ the rooms below, in
// order), every folder has a line in its layout table, and nothing in the repository
// points at a file outside it.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "problems/deck/AnalysisKinds.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kSourceRoot = BEAMROTOR_SOURCE_DIR;

/// Where a source file sits in the import order: its top-level folder's rank, then its room's
/// rank inside that folder. A file may include files of a lower (top, room) pair, or of its own
/// room; rooms of equal rank (the analyses in fem/, the studies in problems/) are peers that
/// never include each other.
struct Layer {
  int top = 0;
  int room = 0;
  std::string roomName;
  /// Inside a room with rooms of its own (problems/deck, problems/output): the inner room's
  /// rank and name; empty for a file directly in the room (the room's entry points, which
  /// may include any inner room and be included by any).
  int inner = 0;
  std::string innerName;
};

const std::map<std::string, int> kTopRank{
    {"fem", 0}, {"elements", 1}, {"meshes", 2}, {"problems", 3}};

/// The rooms of fem/ and problems/, in import order. Files directly in problems/ (the
/// executables' mains) rank above every room.
// clang-format off
const std::map<std::string, std::map<std::string, int>> kRoomRank{
    {"fem", {{"timing", 0}, {"model", 1}, {"assembly", 2}, {"solvers", 3},
             {"static", 4}, {"modal", 4}, {"rotor", 4}, {"transient", 4}, {"stability", 5},
             {"runup", 5}}},
    {"problems", {{"scenes", 0}, {"deck", 1}, {"run", 2}, {"output", 3},
                  {"converge", 4}, {"verify", 4}, {"bench", 4}, {"study", 4},
                  {"cli", 5}, {"python", 5}}}};

/// The inner rooms of a room: the machinery (reading a deck's text, writing files) and the
/// section catalogue (tables of shapes, no deck syntax) first, knowing no analysis family; the beams and frames next, which the other families build on;
/// then the other families, peers that never include each other.
const std::map<std::string, std::map<std::string, int>> kInnerRank{
    {"problems/deck", {{"parse", 0}, {"catalog", 0}, {"structure", 1}, {"rotor", 2},
                       {"transient", 2}, {"crank", 2}, {"torsion", 2}, {"study", 2}}},
    {"problems/output", {{"files", 0}, {"structure", 1}, {"rotor", 2}, {"transient", 2},
                         {"crank", 2}, {"torsion", 2}, {"moving", 2}}}};
// clang-format on

std::optional<Layer> layerOf(const std::string& relative) {
  const fs::path p(relative);
  auto part = p.begin();
  const std::string top = part->string();
  const auto topRank = kTopRank.find(top);
  if (topRank == kTopRank.end()) return std::nullopt;
  Layer layer{topRank->second, 0, "", 0, ""};
  const auto rooms = kRoomRank.find(top);
  if (rooms == kRoomRank.end()) return layer;
  ++part;
  const bool directlyInside = std::next(part) == p.end();
  if (directlyInside) {
    layer.room = 99;
    return layer;
  }
  layer.roomName = part->string();
  const auto room = rooms->second.find(layer.roomName);
  REQUIRE_MESSAGE(room != rooms->second.end(),
                  "folder " << top << "/" << layer.roomName
                            << " has no place in the import order: add it to kRoomRank and "
                               "to the layout table (docs/layout.md)");
  layer.room = room->second;
  const auto inner = kInnerRank.find(top + "/" + layer.roomName);
  ++part;
  if (inner == kInnerRank.end() || std::next(part) == p.end()) return layer;
  layer.innerName = part->string();
  const auto innerRoom = inner->second.find(layer.innerName);
  REQUIRE_MESSAGE(innerRoom != inner->second.end(),
                  "folder " << top << "/" << layer.roomName << "/" << layer.innerName
                            << " has no place in the import order: add it to kInnerRank and "
                               "to the layout table (docs/layout.md)");
  layer.inner = innerRoom->second;
  return layer;
}

bool mayInclude(const Layer& from, const Layer& to) {
  if (from.top != to.top) return to.top < from.top;
  if (from.room != to.room) return to.room < from.room;
  if (from.roomName != to.roomName) return false;
  if (from.innerName.empty() || to.innerName.empty() || from.innerName == to.innerName)
    return true;
  return to.inner < from.inner;
}

std::vector<std::string> sourcesUnder(const std::string& top) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(kSourceRoot / top)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".cpp" || ext == ".hpp"))
      files.push_back(fs::relative(entry.path(), kSourceRoot).generic_string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The analysis types a source text compares a `type` string with (`a.type == "campbell"`,
/// `j.at("type") != "unbalance"`); comparisons with other words (a load's "point") are not.
std::vector<std::string> comparedAnalysisTypes(const std::string& text) {
  const std::vector<std::string> types = beamrotor::analysisTypeNames();
  const std::regex comparison(R"re(type["'()\]]*\s*[!=]=\s*"([^"]*)")re", std::regex::icase);
  std::vector<std::string> found;
  for (std::sregex_iterator m(text.begin(), text.end(), comparison), end; m != end; ++m)
    if (std::find(types.begin(), types.end(), (*m)[1]) != types.end()) found.push_back((*m)[1]);
  return found;
}

}  // namespace

TEST_SUITE("layout") {
  TEST_CASE("includes run one way: down the folders and down the rooms") {
    const std::regex include(R"re(#include "([^"]+)")re");
    int checked = 0;
    for (const std::string top : {"fem", "elements", "meshes", "problems"}) {
      for (const std::string& file : sourcesUnder(top)) {
        const Layer from = *layerOf(file);
        const std::string text = readText(kSourceRoot / file);
        for (std::sregex_iterator m(text.begin(), text.end(), include), end; m != end; ++m) {
          const std::string target = (*m)[1];
          const std::optional<Layer> to = layerOf(target);
          if (!to) continue;  // tests/ and third-party headers
          CAPTURE(file);
          CAPTURE(target);
          CHECK(mayInclude(from, *to));
          ++checked;
        }
      }
    }
    CHECK(checked > 300);  // the walk found the tree (about 600 includes today)
  }

  TEST_CASE("the rule itself: a planted upward include is refused") {
    // A second method for the walk above: the rule judged on known cases.
    CHECK_FALSE(mayInclude(*layerOf("fem/model/Model.hpp"), *layerOf("elements/Beam.hpp")));
    CHECK_FALSE(mayInclude(*layerOf("problems/deck/Deck.hpp"), *layerOf("problems/run/Study.hpp")));
    CHECK_FALSE(
        mayInclude(*layerOf("fem/static/Static.cpp"), *layerOf("fem/rotor/RotorSystem.hpp")));
    CHECK(mayInclude(*layerOf("fem/static/Static.cpp"), *layerOf("fem/solvers/LinearSolver.hpp")));
    CHECK(mayInclude(*layerOf("problems/main.cpp"), *layerOf("problems/cli/App.hpp")));
    CHECK_FALSE(mayInclude(*layerOf("problems/output/files/CsvTable.cpp"),
                           *layerOf("problems/output/rotor/RotorTables.hpp")));
    CHECK_FALSE(mayInclude(*layerOf("problems/output/rotor/RotorTables.cpp"),
                           *layerOf("problems/output/transient/TransientJson.hpp")));
    CHECK(mayInclude(*layerOf("problems/output/rotor/RotorTables.cpp"),
                     *layerOf("problems/output/files/CsvTable.hpp")));
    CHECK_FALSE(mayInclude(*layerOf("problems/deck/parse/Field.cpp"),
                           *layerOf("problems/deck/rotor/DeckRotor.hpp")));
  }

  TEST_CASE("every room has a line in the layout table (docs/layout.md)") {
    const std::string readme = readText(kSourceRoot / "docs" / "layout.md");
    for (const auto& [top, rooms] : kRoomRank) {
      std::set<std::string> onDisk;
      for (const auto& entry : fs::directory_iterator(kSourceRoot / top))
        if (entry.is_directory()) onDisk.insert(entry.path().filename().string());
      for (const std::string& room : onDisk) {
        CAPTURE(top + "/" + room);
        CHECK(rooms.count(room) == 1);
        CHECK(readme.find("| `" + top + "/" + room + "/` |") != std::string::npos);
      }
      for (const auto& [room, rank] : rooms) {
        CAPTURE(top + "/" + room);
        CHECK(onDisk.count(room) == 1);
      }
    }
    for (const auto& [room, inner] : kInnerRank) {
      std::set<std::string> onDisk;
      for (const auto& entry : fs::directory_iterator(kSourceRoot / room))
        if (entry.is_directory() && entry.path().filename() != "paraview")
          onDisk.insert(entry.path().filename().string());
      for (const std::string& name : onDisk) {
        CAPTURE(room + "/" + name);
        CHECK(inner.count(name) == 1);
        CHECK(readme.find("| `" + room + "/" + name + "/` |") != std::string::npos);
      }
      for (const auto& [name, rank] : inner) {
        CAPTURE(room + "/" + name);
        CHECK(onDisk.count(name) == 1);
      }
    }
  }

  TEST_CASE("nothing points outside the repository") {
    // The patterns are split so that this file does not match itself.
    const std::vector<std::string> outside{std::string("SCENES") + ".md",
                                           std::string("../") + "shared",
                                           std::string("/work") + "/", std::string("/home") + "/"};
    const std::set<std::string> textExtensions{".cpp", ".hpp", ".md",   ".yaml",
                                               ".py",  ".txt", ".dict", ".json"};
    std::vector<fs::path> files{kSourceRoot / "README.md", kSourceRoot / "Makefile",
                                kSourceRoot / "CMakeLists.txt", kSourceRoot / ".ci" / "run"};
    for (const std::string top : {"fem", "elements", "meshes", "problems", "tests", "docs"})
      for (const auto& entry : fs::recursive_directory_iterator(kSourceRoot / top))
        if (entry.is_regular_file() && textExtensions.count(entry.path().extension().string()))
          files.push_back(entry.path());
    CHECK(files.size() > 200);
    for (const fs::path& file : files) {
      const std::string text = readText(file);
      for (const std::string& pattern : outside) {
        CAPTURE(file.string());
        CAPTURE(pattern);
        CHECK(text.find(pattern) == std::string::npos);
      }
    }
  }

  TEST_CASE("no analysis type string is compared outside the table of kinds") {
    // A kind is asked of its row (problems/deck/AnalysisKinds.hpp), so that a new kind is one
    // row: a comparison with a type string elsewhere is a place the new row would not reach.
    const std::set<std::string> table{"problems/deck/AnalysisKinds.hpp",
                                      "problems/deck/AnalysisKinds.cpp"};
    int scanned = 0;
    for (const std::string& file : sourcesUnder("problems")) {
      if (table.count(file)) continue;
      CAPTURE(file);
      CHECK(comparedAnalysisTypes(readText(kSourceRoot / file)).empty());
      ++scanned;
    }
    CHECK(scanned > 250);  // the walk found the tree (about 300 files today)
  }

  TEST_CASE("the comparison finder itself: planted comparisons are found") {
    CHECK(comparedAnalysisTypes(R"(if (a.type == "campbell") x();)") ==
          std::vector<std::string>{"campbell"});
    CHECK(comparedAnalysisTypes(R"(if (j.at("type") != "unbalance") x();)") ==
          std::vector<std::string>{"unbalance"});
    CHECK(comparedAnalysisTypes(R"(return q.analysisType() == "transient";)") ==
          std::vector<std::string>{"transient"});
    CHECK(comparedAnalysisTypes(R"(if (type == "point") x();)").empty());
    CHECK(comparedAnalysisTypes(R"(if (options.kind == "rotor") x();)").empty());
  }
}
