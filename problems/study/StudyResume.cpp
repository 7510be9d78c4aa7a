#include "problems/study/StudyResume.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/study/StudyTable.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

/// FNV-1a, 64 bits, as 16 hexadecimal digits: tells one deck text from another.
std::string textHash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

/// The line without its newline; false at the end or for a last line cut short (a row being
/// written when the run was killed: its point is solved again).
bool completeLine(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  return !in.eof();
}

}  // namespace

Json studyIdentity(const StudyPlan& plan, long long points) {
  Json sets = Json::array();
  for (const ParameterOverride& o : plan.overrides) {
    char value[40];  // the value in SI units, whatever its spelling
    std::snprintf(value, sizeof value, "=%.17g", o.value);
    sets.push_back(o.name + value);
  }
  std::string header = studyCsvHeader(plan);
  header.pop_back();  // its last newline (the names and the units line stay apart by theirs)
  return Json{{"deck", plan.deckPath},
              {"deck_text_fnv1a64", textHash(plan.deckText)},
              {"sets", sets},
              {"formulation", plan.formulation},
              {"points", points},
              {"columns", header}};
}

StudyResumption::StudyResumption(const fs::path& dir, const StudyPlan& plan,
                                 const DesignPoints& points)
    : dir_(dir), shape_(blankRow(plan)) {
  const DeckPlace place{0, 0, "--resume " + dir.string()};
  const auto fail = [&](const std::string& why) { throw DeckError(plan.deckPath, place, why); };
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail("no such directory");
  if (isUnfinishedDirectory(dir)) {
    try {
      unfinished_ = std::make_unique<UnfinishedDirectory>(dir);
    } catch (const std::runtime_error& e) {
      fail(e.what());
    }
  }
  std::ifstream identityFile(dir / kResumeFile);
  if (!identityFile)
    fail(std::string("no partial study there (no ") + kResumeFile +
         "; a study that finished has none, and leaves nothing to resume)");
  Json stored;
  try {
    stored = Json::parse(identityFile);
  } catch (const std::exception&) {
    fail(std::string(kResumeFile) + " there is not JSON");
  }
  const Json here = studyIdentity(plan, points.size());
  const auto differs = [&](const char* key, const std::string& what) {
    if (stored.value(key, Json()) != here[key])
      fail("that study " + what + " (there: " + stored.value(key, Json()).dump() +
           ", here: " + here[key].dump() + "); resume it with the deck and options it was run "
           "with");
  };
  differs("deck_text_fnv1a64", "was run on another text of the deck");
  differs("sets", "had other --set overrides");
  differs("formulation", "had another --formulation");
  differs("points", "has another number of points");
  differs("columns", "records other columns");

  table_.open(dir / "study.csv", std::ios::binary);
  // The header's lines: the names, and the units line when there is one.
  std::string header, line;
  const std::string written = studyCsvHeader(plan);
  const long long headerLines = std::count(written.begin(), written.end(), '\n');
  for (long long k = 0; k < headerLines && table_ && completeLine(table_, line); ++k) {
    if (k > 0) header += '\n';
    header += line;
  }
  if (!table_ || header != here["columns"].get<std::string>())
    fail("its study.csv does not begin with the columns of this study");
  const std::streampos rowsStart = table_.tellg();
  for (long long lineNumber = headerLines + 1; completeLine(table_, line); ++lineNumber) {
    const auto row = parseStudyCsvRow(line, shape_);
    const std::string at = "study.csv line " + std::to_string(lineNumber);
    if (!row) fail(at + " is not a row of this study");
    if (row->index >= points.size() || (!done_.empty() && row->index <= done_.runs().back().last))
      fail(at + ": point " + std::to_string(row->index) + " is out of order or out of range");
    if (row->parameters != points.at(row->index))
      fail(at + ": point " + std::to_string(row->index) +
           " has other parameter values there than here (another --sweep, --sample, "
           "--samples, --seed or --sampling?)");
    done_.append(row->index);
  }
  table_.clear();
  table_.seekg(rowsStart);
}

fs::path StudyResumption::destination() const {
  return unfinished_ ? unfinished_->destination() : dir_;
}

bool StudyResumption::nextRow(std::string& line, StudyRow& row) {
  if (!completeLine(table_, line)) return false;
  row = parseStudyCsvRow(line, shape_).value();  // checked when opened
  line += '\n';
  return true;
}

fs::path StudyResumption::pointFiles(long long index) const {
  return dir_ / "points" / std::to_string(index);
}

std::string StudyResumption::finish() {
  if (!unfinished_) return {};
  unfinished_->remove();
  return "removed " + dir_.string() + ", the killed run's directory: its rows are in the results";
}

}  // namespace beamrotor
