// The Python module `beamrotor` (pybind11): the same deck reader, runner and result tables as
// the command line, for notebooks and scripts.
//
//   import beamrotor
//   run = beamrotor.solve("problems/pump_rod.yaml", set={"eta": 0.2})
//   run.results["analyses"][0]["reactions"]     # results.json as plain dicts and lists
//   run.tables["static"]["fields"]["M"]         # a CSV table's column as a NumPy array
//   run.passed, run.checks                      # the deck's closed-form checks
//   run.write("out/pump_rod")                   # the results directory, as `beamrotor solve`
//
// Errors keep the command line's wording: beamrotor.DeckError (bad input, a ValueError) and
// beamrotor.SolveError (an analysis failed, a RuntimeError) carry file, line, column, field
// and message; str(error) is the one-line "file:line:col: field: message".
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "fem/solvers/BlasThreads.hpp"
#include "problems/converge/ConvergeOutput.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/output/Output.hpp"
#include "problems/output/OverlayOutput.hpp"
#include "problems/output/ShownCheck.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/PreparedRun.hpp"
#include "problems/run/Study.hpp"
#include "problems/study/DesignStudyRun.hpp"

namespace py = pybind11;

namespace beamrotor {

namespace {

// 1. Values to Python ------------------------------------------------------------------------

py::object toPython(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(j.get<double>());
    case Json::value_t::string:
      return py::str(j.get<std::string>());
    case Json::value_t::array: {
      py::list list;
      for (const Json& item : j) list.append(toPython(item));
      return list;
    }
    default: {
      py::dict dict;  // keeps results.json's key order
      for (const auto& [key, value] : j.items()) dict[py::str(key)] = toPython(value);
      return dict;
    }
  }
}

/// "static_fields.csv" of stem "static" -> "fields".
std::string tableKey(const std::string& file, const std::string& stem) {
  std::string key = file;
  if (key.rfind(stem + "_", 0) == 0) key.erase(0, stem.size() + 1);
  if (key.size() > 4 && key.compare(key.size() - 4, 4, ".csv") == 0) key.resize(key.size() - 4);
  return key;
}

/// A table's columns: numbers as NumPy arrays (NaN where a cell is empty: a log decrement of
/// an overdamped mode); a column holding text as a list of str, float and None.
py::dict columnsOf(const CsvTable& table) {
  py::dict columns;
  for (const CsvColumn& c : table.columns()) {
    try {
      const std::vector<double> values = table.numbers(c.name);
      columns[py::str(c.name)] = py::array_t<double>(py::ssize_t(values.size()), values.data());
    } catch (const std::invalid_argument&) {  // text in some row
      py::list cells;
      const int position = table.column(c.name) - 1;
      for (std::size_t r = 0; r < table.rowCount(); ++r)
        std::visit([&](const auto& cell) { cells.append(cell); },
                   table.cell(r, std::size_t(position)));
      columns[py::str(c.name)] = std::move(cells);
    }
  }
  return columns;
}

py::dict unitsOf(const CsvTable& table) {
  py::dict units;
  for (const CsvColumn& c : table.columns()) units[py::str(c.name)] = c.unit;
  return units;
}

/// write()'s keyword arguments as choices over the deck's: charts="png"|"svg"|"both"|"none".
DeckOutput outputFrom(const std::optional<std::string>& charts, std::optional<bool> pointFiles) {
  DeckOutput output;
  if (charts) {
    output.charts = chartFormatNamed(*charts);
    if (!output.charts)
      throw py::value_error("charts: '" + *charts + "' is not one of " +
                            joinNames(chartFormatNames()));
  }
  output.pointFiles = pointFiles;
  return output;
}

// 2. Results as Python objects ---------------------------------------------------------------

/// One solved run: its results.json document and its tables, built once by the same code
/// that writes the results directory.
class PythonRun {
 public:
  PythonRun(RunResult run, DeckOutput output) : run_(std::move(run)), output_(output) {
    // Tables in the output units chosen (the deck's, or solve(units=...)'s over them); the
    // results stay SI.
    OutputChoices tablesIn;
    tablesIn.units = output_.units;
    PreparedRun prepared = prepareRun(run_, tablesIn);
    results_ = toPython(wholeResults(prepared));
    for (const PreparedAnalysis& a : prepared.analyses) {
      py::dict tables, units;
      for (const auto& [file, table] : a.tables()) {
        tables[py::str(tableKey(file, a.stem))] = columnsOf(*table);
        units[py::str(tableKey(file, a.stem))] = unitsOf(*table);
      }
      tables_[py::str(a.outcome->name)] = tables;
      units_[py::str(a.outcome->name)] = units;
    }
  }

  py::object results() const { return results_; }
  py::dict tables() const { return tables_; }
  py::dict units() const { return units_; }
  py::object checks() const { return results_["checks"]; }
  bool passed() const {
    for (const Check& c : run_.checks)
      if (!c.pass()) return false;
    return true;
  }
  py::dict parameters() const {
    py::dict p;
    for (const auto& [name, value] : run_.parameters) p[py::str(name)] = value;
    return p;
  }
  /// Node coordinates (m, global frame), one row per node.
  py::array_t<double> nodes() const {
    const Model& model = *run_.model;
    py::array_t<double> xyz({py::ssize_t(model.nodeCount()), py::ssize_t(3)});
    auto view = xyz.mutable_unchecked<2>();
    for (int n = 0; n < model.nodeCount(); ++n)
      for (int k = 0; k < 3; ++k) view(n, k) = model.nodes()[std::size_t(n)][k];
    return xyz;
  }
  /// The nodal displacements of a static analysis: one row per node, columns ux uy uz rx ry rz.
  py::array_t<double> displacements(const std::string& analysis) const {
    for (const AnalysisOutcome& a : run_.analyses)
      if (a.name == analysis) {
        const StaticResult* statics = staticsOf(a);
        if (!statics) throw py::value_error("analysis '" + analysis + "' is not static");
        const NodalField& u = statics->displacement;
        py::array_t<double> out({py::ssize_t(u.rows()), py::ssize_t(u.cols())});
        auto view = out.mutable_unchecked<2>();
        for (Eigen::Index r = 0; r < u.rows(); ++r)
          for (Eigen::Index c = 0; c < u.cols(); ++c) view(r, c) = u(r, c);
        return out;
      }
    throw py::key_error("no analysis named '" + analysis + "'");
  }
  void write(const std::filesystem::path& dir, const std::optional<std::string>& charts) const {
    const OutputChoices choices = chooseOutput(output_, outputFrom(charts, std::nullopt));
    py::gil_scoped_release free;
    writeRunOutputs(run_, dir, choices);
  }
  std::string repr() const {
    return "<beamrotor.Run " + run_.deckName + ": " + std::to_string(run_.analyses.size()) +
           " analyses, " + std::to_string(run_.checks.size()) + " checks, " +
           (passed() ? "all pass" : "some fail") + ">";
  }

 private:
  RunResult run_;
  DeckOutput output_;  ///< the deck's `output:` choices
  py::object results_;
  py::dict tables_, units_;
};

/// A deck solved over the values of one parameter.
class PythonSweep {
 public:
  PythonSweep(SweepResult sweep, DeckOutput output) : sweep_(std::move(sweep)), output_(output) {
    for (const RunResult& r : sweep_.runs) runs_.emplace_back(r, output);
  }
  const std::string& parameter() const { return sweep_.parameter; }
  py::array_t<double> values() const {
    return py::array_t<double>(py::ssize_t(sweep_.values.size()), sweep_.values.data());
  }
  const std::vector<PythonRun>& runs() const { return runs_; }
  void write(const std::filesystem::path& dir, const std::optional<std::string>& charts,
             std::optional<bool> pointFiles) const {
    const OutputChoices choices = chooseOutput(output_, outputFrom(charts, pointFiles));
    py::gil_scoped_release free;
    writeSweepOutputs(sweep_, dir, choices);
  }

 private:
  SweepResult sweep_;
  DeckOutput output_;
  std::vector<PythonRun> runs_;
};

// 3. Requests from Python --------------------------------------------------------------------

/// {"eta": 0.2, "w0": "2*mm"} -> {"eta=0.2", "w0=2*mm"}: numbers at full precision, text as
/// written (an expression the deck reader evaluates).
std::vector<std::string> overridesFrom(const py::dict& values) {
  std::vector<std::string> sets;
  for (const auto& [key, value] : values) {
    const std::string name = py::str(key);
    if (py::isinstance<py::bool_>(value))
      throw py::type_error("set: '" + name + "' must be a number or an expression, not a bool");
    if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.17g", value.cast<double>());
      sets.push_back(name + "=" + buffer);
    } else if (py::isinstance<py::str>(value)) {
      sets.push_back(name + "=" + value.cast<std::string>());
    } else {
      throw py::type_error("set: '" + name + "' must be a number or an expression (str)");
    }
  }
  return sets;
}

/// solve()'s `units`: {"length": "mm"} or "length=mm,force=kN"; a bad one is a ValueError.
OutputUnits unitsFrom(const py::object& units) {
  try {
    if (units.is_none()) return {};
    if (py::isinstance<py::str>(units)) return parseOutputUnits(units.cast<std::string>());
    if (!py::isinstance<py::dict>(units))
      throw py::type_error("units: a dict {quantity: unit} or a str 'length=mm,force=kN'");
    OutputUnits out;
    for (const auto& [quantity, unit] : units.cast<py::dict>())
      out.set(py::str(quantity), py::str(unit));
    return out;
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("units: ") + e.what());
  }
}

/// The deck read with solve()'s arguments and solved, the GIL let go meanwhile.
Study solvedStudy(const std::filesystem::path& deck, const py::dict& set,
                  const std::string& sweep, const std::string& formulation, bool noSweep) {
  StudyRequest request;
  request.deckPath = deck.string();
  request.sets = overridesFrom(set);
  request.sweep = sweep;
  request.formulation = formulation;
  request.noSweep = noSweep;
  py::gil_scoped_release free;
  return solveStudy(request);
}

py::object solve(const std::filesystem::path& deck, const py::dict& set, const std::string& sweep,
                 const std::string& formulation, bool noSweep, const py::object& units) {
  const OutputUnits chosen = unitsFrom(units);
  Study study = solvedStudy(deck, set, sweep, formulation, noSweep);
  DeckOutput output = study.deck.output;
  output.units = output.units.overlaid(chosen);
  if (study.sweep) return py::cast(PythonSweep(std::move(*study.sweep), output));
  return py::cast(PythonRun(std::move(*study.run), output));
}

// 4. Design studies ------------------------------------------------------------------------

/// The cells of one line of a CSV file beamrotor wrote: text cells quoted ("" a quote inside),
/// numbers bare, an empty cell empty.
std::vector<std::string> csvLine(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      cells.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

/// study.csv as columns: a column whose every cell is a number or empty as a NumPy array (NaN
/// where empty), read back to the same bits the study computed (the file holds each number's
/// shortest exact decimal); any other as a list of str.
/// `units`, when given, gets each column's unit from the table's units line ("# units: ...").
py::dict studyColumns(const std::filesystem::path& file, py::dict* units = nullptr) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = csvLine(line);
  std::vector<std::vector<std::string>> cells(names.size());
  const std::string unitsLine = "# units: ";
  while (std::getline(in, line)) {
    if (line.rfind(unitsLine, 0) == 0) {
      const std::vector<std::string> unit = csvLine(line.substr(unitsLine.size()));
      if (units)
        for (std::size_t c = 0; c < names.size() && c < unit.size(); ++c)
          (*units)[py::str(names[c])] = unit[c];
      continue;
    }
    const std::vector<std::string> row = csvLine(line);
    for (std::size_t c = 0; c < names.size(); ++c) cells[c].push_back(c < row.size() ? row[c] : "");
  }
  py::dict columns;
  for (std::size_t c = 0; c < names.size(); ++c) {
    std::vector<double> numbers;
    bool numeric = true;
    for (const std::string& cell : cells[c]) {
      if (cell.empty()) {
        numbers.push_back(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      char* end = nullptr;
      numbers.push_back(std::strtod(cell.c_str(), &end));
      numeric = numeric && end == cell.c_str() + cell.size();
    }
    if (numeric)
      columns[py::str(names[c])] = py::array_t<double>(py::ssize_t(numbers.size()), numbers.data());
    else
      columns[py::str(names[c])] = py::cast(cells[c]);
  }
  return columns;
}

/// A design study run from Python: its table, summary and worst point.
struct PythonStudy {
  py::dict table;         ///< study.csv's columns
  py::dict units;         ///< each column's unit, as study.csv names it
  py::object summary;     ///< summary.json
  py::object worst;       ///< the worst point's Run, or None
  std::filesystem::path directory;
};

py::object study(const std::filesystem::path& deck, const std::vector<std::string>& sweep,
                 const py::dict& sample, std::optional<long long> samples,
                 const std::vector<std::string>& outputs, int threads,
                 std::optional<std::uint64_t> seed, const std::string& sampling,
                 const py::dict& set, const std::optional<std::filesystem::path>& out,
                 const py::object& units) {
  DesignStudyRequest request;
  request.units = unitsFrom(units);
  request.deckPath = deck.string();
  request.sets = overridesFrom(set);
  request.study.sweeps = sweep;
  for (const auto& [name, distribution] : sample)
    request.study.samples.push_back(py::str(name).cast<std::string>() + "=" +
                                    py::str(distribution).cast<std::string>());
  request.study.count = samples;
  request.study.outputs = outputs;
  request.study.seed = seed;
  request.study.sampling = sampling;
  request.threads = threads;
  // Without `out`, the study's directory is a temporary one, removed once read.
  const bool temporary = !out;
  std::string scratch = "beamrotor-study-";  // appended: GCC 12's -Wrestrict on "..." + temp
  scratch += std::to_string(::getpid());
  scratch += "-";
  scratch += std::to_string(reinterpret_cast<std::uintptr_t>(&request));
  const std::filesystem::path dir = out ? *out : std::filesystem::temp_directory_path() / scratch;
  request.outDir = dir.string();
  DesignStudyOutcome outcome;
  {
    py::gil_scoped_release free;
    outcome = runDesignStudy(request);
  }
  py::dict columnUnits;
  py::dict table = studyColumns(outcome.dir / "study.csv", &columnUnits);
  PythonStudy result{table, columnUnits, toPython(outcome.summary), py::none(),
                     temporary ? std::filesystem::path() : outcome.dir};
  if (temporary) std::filesystem::remove_all(outcome.dir);
  // The worst point solved in full, as the command line writes it into worst/.
  if (outcome.summary.contains("worst_point") &&
      outcome.summary["worst_point"].contains("directory")) {
    // A copy: `set` may be the keyword's default dict, which pybind11 shares between calls.
    py::dict at;
    for (const auto& [name, value] : set) at[name] = value;
    for (const auto& [name, value] : outcome.summary["worst_point"]["parameters"].items())
      at[py::str(name)] = value.get<double>();
    result.worst = solve(deck, at, "", "", true, units);
  }
  return py::cast(std::move(result));
}

// 5. Checks, convergence studies and overlays, in the output units -----------------------

/// check(): the deck's checks as `beamrotor check` prints them, in the output units: one dict
/// per check (per value and check for a sweep, `at` naming the value).
py::list check(const std::filesystem::path& deck, const py::dict& set, const std::string& sweep,
               const std::string& formulation, bool noSweep, const py::object& units) {
  const OutputUnits chosen = unitsFrom(units);
  const Study study = solvedStudy(deck, set, sweep, formulation, noSweep);
  const OutputUnits shownIn = study.deck.output.units.overlaid(chosen);
  py::list checks;
  const auto add = [&](const RunResult& run, const py::object& at) {
    for (const Check& c : run.checks) {
      const ShownCheck shown = shownCheck(c, shownIn);
      py::dict entry;
      entry["name"] = c.name;
      entry["quantity"] = c.quantity;
      entry["computed"] = shown.computed;
      entry["reference"] = shown.reference;
      entry["error"] = shown.error;
      entry["tolerance"] = shown.tolerance;
      entry["absolute"] = shown.absolute;
      entry["unit"] = shown.unit;
      entry["pass"] = c.pass();
      if (shown.paper) entry["paper"] = *shown.paper;
      if (!at.is_none()) entry["at"] = at;
      checks.append(entry);
    }
  };
  if (study.run) {
    add(*study.run, py::none());
  } else {
    const SweepResult& s = *study.sweep;
    const OutputUnits::Shown value = shownIn.valueIn(s.unit, {1, s.unit});
    for (std::size_t i = 0; i < s.runs.size(); ++i) {
      py::dict at;
      at["parameter"] = s.parameter;
      at["value"] = s.values[i] * value.factor;
      at["unit"] = value.unit;
      add(s.runs[i], at);
    }
  }
  return checks;
}

/// Tables as Python: {key: columns} and {key: {column: unit}}, the key the table's file name
/// without `stem`_ and .csv.
void tablesToPython(const std::vector<CsvTable>& tables, const std::string& stem,
                    py::dict& columns, py::dict& units) {
  for (const CsvTable& t : tables) {
    columns[py::str(tableKey(t.title(), stem))] = columnsOf(t);
    units[py::str(tableKey(t.title(), stem))] = unitsOf(t);
  }
}

/// A convergence study run from Python: convergence.json (as measured) and the tables.
struct PythonConvergence {
  py::object results;    ///< convergence.json
  py::dict tables;       ///< per method: its table's columns, in the output units
  py::dict units;        ///< per method: each column's unit
};

py::object converge(const std::filesystem::path& deck, const py::dict& set,
                    const std::string& quantity, int levels, int repeats,
                    const std::optional<std::filesystem::path>& out, const py::object& units) {
  const OutputUnits chosen = unitsFrom(units);
  const DeckSource source = loadDeckFile(deck.string());
  std::vector<ParameterOverride> overrides;
  for (const std::string& s : overridesFrom(set))
    overrides.push_back(parseOverride(s, source.path));
  const Deck d = readDeck(source, overrides);
  const OutputUnits shownIn = d.output.units.overlaid(chosen);
  ConvergeStudy study;
  {
    py::gil_scoped_release free;
    study = runConvergence(d, ConvergeOptions{quantity, levels, repeats});
    if (out) writeConvergenceOutputs(study, *out, shownIn);
  }
  PythonConvergence result{toPython(convergenceJson(study)), {}, {}};
  tablesToPython(convergenceTables(study, shownIn), "convergence", result.tables, result.units);
  return py::cast(std::move(result));
}

/// An overlay run from Python: each deck's fields table along its line, in the output units.
struct PythonOverlay {
  py::dict tables;  ///< per deck (its label): the fields table's columns
  py::dict units;   ///< per deck: each column's unit
  bool drawn = false;  ///< whether the chart was drawn (written with `out` and gnuplot)
};

py::object overlay(const std::vector<std::filesystem::path>& decks, const py::dict& set,
                   const std::string& quantity, const std::optional<std::filesystem::path>& out,
                   const py::object& units) {
  const OutputUnits chosen = unitsFrom(units);
  const std::vector<Diagram> shown = overlaidDiagrams(quantity);
  if (shown.empty())
    throw py::value_error("quantity: '" + quantity + "' is not 'all' nor one of the diagrams");
  if (decks.size() < 2) throw py::value_error("decks: an overlay needs two or more decks");
  std::vector<std::string> paths;
  for (const std::filesystem::path& d : decks) paths.push_back(d.string());
  const std::vector<std::string> sets = overridesFrom(set);
  std::vector<Study> studies;
  {
    py::gil_scoped_release free;
    studies = solveOverlaid(paths, sets);
  }
  const OutputUnits shownIn = studies.front().deck.output.units.overlaid(chosen);
  std::vector<OverlaidRun> runs;
  for (const Study& s : studies) runs.push_back({s.run->deckName, &*s.run});
  PythonOverlay result;
  for (const OverlaidRun& r : runs) {
    const CsvTable table = overlaidTable(r, shownIn);
    result.tables[py::str(r.label)] = columnsOf(table);
    result.units[py::str(r.label)] = unitsOf(table);
  }
  if (out) {
    py::gil_scoped_release free;
    writeDirectoryAtomically(*out, [&](const std::filesystem::path& temporary) {
      result.drawn = writeOverlay(temporary, runs, shown, shownIn);
    });
  }
  return py::cast(std::move(result));
}

py::dict parameters(const std::filesystem::path& deck) {
  const Deck d = readDeck(loadDeckFile(deck));
  py::dict p;
  for (const auto& [name, value] : d.parameters) p[py::str(name)] = value;
  return p;
}

// 6. Errors ------------------------------------------------------------------------------

/// Imports NumPy, or fails the import of this module with an ImportError that names NumPy,
/// the Python running and the one the module was built for (pybind11 alone says
/// "initialization failed", and only the chained error names NumPy).
void requireNumPy() {
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set& e) {
    const py::module_ sys = py::module_::import("sys");
    std::string message = "beamrotor needs NumPy, which this Python cannot import (";
    message += e.what();
    const std::string version = py::str(sys.attr("version")).cast<std::string>();
    message += "). The module was built for Python ";
    message += std::to_string(PY_MAJOR_VERSION);
    message += ".";
    message += std::to_string(PY_MINOR_VERSION);
    message += "; this is ";
    message += py::str(sys.attr("executable")).cast<std::string>();
    message += ", Python ";
    message += version.substr(0, version.find(' '));
    message += ". Install NumPy for it (Debian: apt install python3-numpy).";
    // A std::exception leaving the module's initialisation becomes an ImportError with this text.
    throw std::runtime_error(message);
  }
}

/// Raises `type` with the diagnostic's parts as attributes.
void raise(const py::object& type, const DeckDiagnostic& e) {
  py::object error = type(py::str(e.what()));
  error.attr("file") = e.file();
  error.attr("line") = e.place().line;
  error.attr("column") = e.place().column;
  error.attr("field") = e.place().field;
  error.attr("message") = e.message();
  PyErr_SetObject(type.ptr(), error.ptr());
}

}  // namespace

}  // namespace beamrotor

PYBIND11_MODULE(beamrotor, m) {
  using namespace beamrotor;
  m.doc() = "beamrotor: finite-element beams, frames and rotors; decks solved from Python";
  m.attr("__version__") = BEAMROTOR_VERSION;
  // pybind11 finds NumPy's C API on first use, in a function-local static whose initialiser
  // imports NumPy, and an import can hand the GIL to another thread: two threads making their
  // first Run at once then deadlocked (one in the import waiting for the GIL, the other holding
  // the GIL waiting for the static). Made here, while the import of this module holds the GIL.
  requireNumPy();
  py::array_t<double>(py::ssize_t(0));
  useOneBlasThreadPerCall();

  static py::exception<DeckError> deckError(m, "DeckError", PyExc_ValueError);
  static py::exception<DeckSolveError> solveError(m, "SolveError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const DeckError& e) {
      raise(deckError, e);
    } catch (const DeckSolveError& e) {
      raise(solveError, e);
    }
  });

  py::class_<PythonRun>(m, "Run", "One solved instance of a deck.")
      .def_property_readonly("results", &PythonRun::results,
                             "results.json of the run as dicts and lists")
      .def_property_readonly("tables", &PythonRun::tables,
                             "tables[analysis][table][column]: the CSV tables' columns as "
                             "NumPy arrays (text columns as lists)")
      .def_property_readonly("units", &PythonRun::units,
                             "units[analysis][table][column]: each column's unit")
      .def_property_readonly("checks", &PythonRun::checks,
                             "the deck's checks: name, quantity, computed, reference, "
                             "rel_error, tolerance, pass")
      .def_property_readonly("passed", &PythonRun::passed, "whether every check passes")
      .def_property_readonly("parameters", &PythonRun::parameters, "parameter values used")
      .def_property_readonly("nodes", &PythonRun::nodes, "node coordinates (m), n x 3")
      .def("displacements", &PythonRun::displacements, py::arg("analysis"),
           "nodal displacements of a static analysis, n x 6 (ux uy uz rx ry rz; m, rad)")
      .def("write", &PythonRun::write, py::arg("directory"), py::kw_only(),
           py::arg("charts") = py::none(),
           "writes the results directory, as `beamrotor solve --out`; charts: 'png', 'svg', "
           "'both' or 'none' (default: the deck's output: charts, else png)")
      .def("__repr__", &PythonRun::repr);

  py::class_<PythonSweep>(m, "Sweep", "A deck solved over the values of one parameter.")
      .def_property_readonly("parameter", &PythonSweep::parameter)
      .def_property_readonly("values", &PythonSweep::values)
      .def_property_readonly("runs", &PythonSweep::runs, "one Run per value")
      .def("write", &PythonSweep::write, py::arg("directory"), py::kw_only(),
           py::arg("charts") = py::none(), py::arg("point_files") = py::none(),
           "writes the sweep's results directory, as `beamrotor solve --out`; charts as "
           "Run.write; point_files: also every value's own results directory");

  m.def("solve", &beamrotor::solve, py::arg("deck"), py::kw_only(), py::arg("set") = py::dict(),
        py::arg("sweep") = "", py::arg("formulation") = "", py::arg("sweep_off") = false,
        py::arg("units") = py::none(),
        "Reads a deck, applies `set` ({name: number or expression}) and solves it. Returns a "
        "Run, or a Sweep when the deck (or `sweep`, e.g. 'eta=0:0.4:4') sweeps a parameter; "
        "`sweep_off` solves the parameters' own values. `units` ({'length': 'mm'} or "
        "'length=mm,force=kN') sets the units of run.tables and of write() over the deck's "
        "output: units (run.units names them; run.results stays SI). Raises DeckError or "
        "SolveError.");
  py::class_<PythonStudy>(m, "Study", "A design study: its table, summary and worst point.")
      .def_readonly("table", &PythonStudy::table,
                    "study.csv's columns: NumPy arrays (text columns as lists of str)")
      .def_readonly("units", &PythonStudy::units,
                    "each column's unit, as study.csv's units line names it (the table keeps "
                    "these units whatever `units` chose)")
      .def_readonly("summary", &PythonStudy::summary,
                    "summary.json as dicts and lists (in the columns' units, which it names)")
      .def_readonly("worst", &PythonStudy::worst, "the worst point's Run (None without one)")
      .def_property_readonly(
          "directory",
          [](const PythonStudy& s) -> py::object {
            return s.directory.empty() ? py::none() : py::cast(s.directory);
          },
          "the results directory written (`out`), or None");

  m.def("study", &beamrotor::study, py::arg("deck"), py::kw_only(),
        py::arg("sweep") = std::vector<std::string>{}, py::arg("sample") = py::dict(),
        py::arg("samples") = py::none(), py::arg("outputs") = std::vector<std::string>{},
        py::arg("threads") = 1, py::arg("seed") = py::none(), py::arg("sampling") = "",
        py::arg("set") = py::dict(), py::arg("out") = py::none(), py::arg("units") = py::none(),
        "Runs a design study as `beamrotor study` does: `sweep` grid axes ('eta=0:0.4:99'), "
        "`sample` {name: 'normal(1e-3,0.2e-3)'} with `samples` points, `outputs` ('stress max "
        "<= 150 MPa'), on `threads` threads. Returns a Study: its table (the columns of "
        "study.csv, the same numbers to the bit), summary and worst point's Run; `out` keeps "
        "the results directory there. `units` (as solve's) sets the units of the worst "
        "point's Run and results directory, as --units does.");
  m.def("check", &beamrotor::check, py::arg("deck"), py::kw_only(), py::arg("set") = py::dict(),
        py::arg("sweep") = "", py::arg("formulation") = "", py::arg("sweep_off") = false,
        py::arg("units") = py::none(),
        "Solves the deck as solve() does and returns its checks as `beamrotor check` prints "
        "them: a list of dicts {name, quantity, computed, reference, error, tolerance, "
        "absolute, unit, pass[, paper][, at]}, the values in `units` (as solve's) over the "
        "deck's output: units; error and tolerance are relative, or absolute in `unit` when "
        "the reference is 0 (`absolute`). A sweep gives each value's checks, `at` "
        "{parameter, value, unit} naming the value.");
  py::class_<PythonConvergence>(m, "Convergence", "A convergence study: its results and tables.")
      .def_readonly("results", &PythonConvergence::results,
                    "convergence.json as dicts and lists (as measured: SI)")
      .def_readonly("tables", &PythonConvergence::tables,
                    "tables[method][column]: each method's table as NumPy arrays, in the "
                    "output units")
      .def_readonly("units", &PythonConvergence::units, "units[method][column]");
  m.def("converge", &beamrotor::converge, py::arg("deck"), py::kw_only(),
        py::arg("set") = py::dict(), py::arg("quantity") = "", py::arg("levels") = 5,
        py::arg("repeats") = 3, py::arg("out") = py::none(), py::arg("units") = py::none(),
        "Runs `beamrotor converge` on the deck: `quantity` (default: the first that changes "
        "with the discretisation) on `levels` meshes or time steps, each timed as the median "
        "of `repeats` runs. Returns a Convergence; `out` also writes its results directory. "
        "`units` (as solve's) sets the units of its tables and charts.");
  py::class_<PythonOverlay>(m, "Overlay", "Several decks' static diagrams along their lines.")
      .def_readonly("tables", &PythonOverlay::tables,
                    "tables[deck][column]: each deck's fields table, in the output units")
      .def_readonly("units", &PythonOverlay::units, "units[deck][column]")
      .def_readonly("drawn", &PythonOverlay::drawn, "whether the chart was drawn");
  m.def("overlay", &beamrotor::overlay, py::arg("decks"), py::kw_only(),
        py::arg("set") = py::dict(), py::arg("quantity") = "all", py::arg("out") = py::none(),
        py::arg("units") = py::none(),
        "Runs `beamrotor overlay` on two or more decks (each without its sweep): their fields "
        "tables, and with `out` the results directory with the chart of `quantity` "
        "(deflection, rotation, moment, force, stress, shear or all). `units` (as solve's) "
        "sets the units of the tables and the chart over the first deck's output: units.");
  m.def("parameters", &beamrotor::parameters, py::arg("deck"),
        "The deck's parameters and their values, in deck order.");
}
