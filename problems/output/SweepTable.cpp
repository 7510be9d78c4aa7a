// Sweep quantities and sweep.csv (see SweepTable.hpp), read from each value's results.json.
#include "problems/output/SweepTable.hpp"

#include <algorithm>
#include <stdexcept>

namespace beamrotor {

namespace {

/// The entry of analysis `name` in a run's document.
const Json& analysisNamed(const Json& runDoc, const std::string& name) {
  for (const Json& a : runDoc.at("analyses"))
    if (a.at("name") == name) return a;
  throw std::runtime_error("this sweep value has no analysis '" + name + "'");
}

const Json& checkNamed(const Json& runDoc, const std::string& name) {
  for (const Json& c : runDoc.at("checks"))
    if (c.at("name") == name) return c;
  throw std::runtime_error("this sweep value has no check '" + name + "'");
}

/// member[key] of a JSON object, with an error naming what is missing.
const Json& required(const Json& object, const std::string& key, const std::string& what) {
  if (!object.contains(key)) throw std::runtime_error("this sweep value has no " + what);
  return object[key];
}

void addStatic(const Json& a, std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  for (const auto& [support, components] : a.at("reactions").items())
    for (const auto& [component, value] : components.items()) {
      const std::string unit = component[0] == 'm' ? "N m" : "N";
      out.push_back(
          {SweepGroup::reaction,
           name,
           support + " " + component,
           {name + "." + support + "." + component, unit},
           [name, support, component](const Json& doc) {
             const Json& reactions = analysisNamed(doc, name).at("reactions");
             const std::string what = "reaction " + support + " " + component;
             return required(required(reactions, support, what), component, what).get<double>();
           }});
    }
  for (const auto& [key, label] :
       {std::pair<std::string, std::string>{"max_stress", "largest normal stress"},
        {"max_shear", "largest shear stress"}})
    if (a.contains(key))
      out.push_back(
          {SweepGroup::stress,
           name,
           label,
           {name + "." + key, "Pa"},
           [name, key, label](const Json& doc) {
             return required(analysisNamed(doc, name), key, label).at("value").get<double>();
           }});
}

/// A second-order static analysis' amplification against first order, each on its own panel.
void addSecondOrder(const Json& a, std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  for (const char* key : {"moment_amplification", "stress_amplification"})
    out.push_back({SweepGroup::extreme,
                   name,
                   key,
                   {name + "." + key, ""},
                   [name, key = std::string(key)](const Json& doc) {
                     return required(required(analysisNamed(doc, name), "second_order",
                                              "second-order results"),
                                     key, key)
                         .get<double>();
                   }});
}

/// A buckling analysis' lowest positive load factor (the one that decides), when every value
/// of the sweep has one (a load that compresses nothing has none).
void addBuckling(const Json& a, const std::vector<Json>& runDocs,
                 std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  for (const Json& doc : runDocs)
    if (analysisNamed(doc, name).at("load_factors").empty()) return;
  out.push_back({SweepGroup::extreme,
                 name,
                 "lowest load factor",
                 {name + ".load_factor_1", ""},
                 [name](const Json& doc) {
                   const Json& f = analysisNamed(doc, name).at("load_factors");
                   if (f.empty())
                     throw std::runtime_error("this sweep value has no positive load factor");
                   return f[0].get<double>();
                 }});
}

void addModal(const Json& a, std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  for (std::size_t k = 0; k < a.at("frequencies_hz").size(); ++k) {
    const std::string mode = "mode " + std::to_string(k + 1);
    out.push_back({SweepGroup::frequency,
                   name,
                   mode,
                   {name + ".f" + std::to_string(k + 1), "Hz"},
                   [name, k, mode](const Json& doc) {
                     const Json& f = analysisNamed(doc, name).at("frequencies_hz");
                     if (k >= f.size()) throw std::runtime_error("this sweep value has no " + mode);
                     return f[k].get<double>();
                   }});
  }
}

void addTransient(const Json& a, std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  for (const auto& [key, value] : a.at("maxima").items()) {
    // <history>_max carries its history's unit.
    const std::string history = key.substr(0, key.size() - 4);
    const std::string unit = a.at("histories").at(history).at("unit");
    out.push_back({SweepGroup::extreme,
                   name,
                   key,
                   {name + "." + key, unit},
                   [name, key](const Json& doc) {
                     return required(analysisNamed(doc, name).at("maxima"), key, key)
                         .get<double>();
                   }});
  }
}

}  // namespace

std::vector<SweepQuantity> sweepQuantities(const std::vector<Json>& runDocs) {
  std::vector<SweepQuantity> out;
  for (const Json& a : runDocs.at(0).at("analyses")) {
    if (a.contains("reactions")) addStatic(a, out);
    if (a.contains("second_order")) addSecondOrder(a, out);
    if (a.contains("load_factors")) addBuckling(a, runDocs, out);
    if (a.contains("frequencies_hz")) addModal(a, out);
    if (a.contains("maxima")) addTransient(a, out);
  }
  const Json reported = runDocs.at(0).value("reported", Json::object());
  for (const auto& [name, value] : reported.items())
    out.push_back({SweepGroup::reported, "", name, {name, ""}, [name](const Json& doc) {
                     return required(required(doc, "reported", "reported values"), name,
                                     "reported value " + name)
                         .get<double>();
                   }});
  std::vector<std::string> checks;
  for (const Json& doc : runDocs)
    for (const Json& c : doc.at("checks")) {
      const std::string name = c.at("name");
      if (std::find(checks.begin(), checks.end(), name) == checks.end()) checks.push_back(name);
    }
  for (const std::string& name : checks) {
    out.push_back({SweepGroup::check, "", name, {"check." + name, ""},
                   [name](const Json& doc) {
                     return checkNamed(doc, name).at("computed").get<double>();
                   },
                   true});
    out.push_back({SweepGroup::checkPass,
                   "",
                   name + " passes",
                   {"check." + name + ".pass", ""},
                   [name](const Json& doc) {
                     return checkNamed(doc, name).at("pass").get<bool>() ? 1.0 : 0.0;
                   },
                   true});
  }
  return out;
}

CsvTable sweepTable(const std::string& title, const SweepResult& sweep,
                    const std::vector<Json>& runDocs,
                    const std::vector<SweepQuantity>& quantities) {
  std::vector<CsvColumn> columns{{sweep.parameter, sweep.unit}};
  for (const SweepQuantity& q : quantities) columns.push_back(q.column);
  CsvTable table(title, columns);
  for (std::size_t i = 0; i < runDocs.size(); ++i) {
    std::vector<CsvCell> row{sweep.values.at(i)};
    for (const SweepQuantity& q : quantities) {
      try {
        row.push_back(q.read(runDocs[i]));
      } catch (const std::runtime_error& e) {
        if (q.optional) {
          row.push_back(std::string());
          continue;
        }
        throw std::runtime_error(title + ": " + sweep.parameter + " = " +
                                 exactDecimal(sweep.values[i]) + ": " + e.what());
      }
    }
    table.addRow(std::move(row));
  }
  return table;
}

}  // namespace beamrotor
