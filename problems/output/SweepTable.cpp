// Sweep quantities and sweep.csv (see SweepTable.hpp), read from each value's results.json.
#include "problems/output/SweepTable.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "problems/deck/AnalysisKinds.hpp"

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

/// A campbell analysis: each critical speed (those some value finds; a value that finds fewer
/// leaves the cell empty), the smallest log decrement over its speeds and, when some value has
/// one, the onset of instability.
void addCampbell(const Json& a, const std::vector<Json>& runDocs,
                 std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  std::size_t count = 0;
  bool onset = false;
  for (const Json& doc : runDocs) {
    const Json& c = analysisNamed(doc, name);
    count = std::max(count, c.at("critical_speeds").size());
    onset = onset || !c.value("instability_onset", Json(nullptr)).is_null();
  }
  for (std::size_t k = 0; k < count; ++k) {
    const std::string label = "critical speed " + std::to_string(k + 1);
    out.push_back({SweepGroup::criticalSpeed,
                   name,
                   label,
                   {name + ".critical_speed_" + std::to_string(k + 1), "rpm"},
                   [name, k, label](const Json& doc) {
                     const Json& c = analysisNamed(doc, name).at("critical_speeds");
                     if (k >= c.size()) throw std::runtime_error("this sweep value has no " + label);
                     return c[k].at("rpm").get<double>();
                   },
                   true});
  }
  // entry[field] of a figure that may be null (left empty then), on a panel of its own
  const auto figure = [&](const std::string& label, const std::string& entry,
                          const std::string& field, const std::string& unit) {
    out.push_back({SweepGroup::extreme,
                   name,
                   label,
                   {name + "." + entry, unit},
                   [name, label, entry, field](const Json& doc) {
                     const Json& f = analysisNamed(doc, name).at(entry);
                     if (f.is_null() || f.at(field).is_null())
                       throw std::runtime_error("this sweep value has no " + label);
                     return f.at(field).get<double>();
                   },
                   true});
  };
  if (a.contains("smallest_log_decrement"))
    figure("smallest log decrement", "smallest_log_decrement", "value", "");
  if (onset) figure("onset of instability", "instability_onset", "rpm", "rpm");
}

/// An unbalance analysis: each response point's largest orbit (semi-major axis).
void addUnbalance(const Json& a, std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  for (const auto& [point, response] : a.at("response").items())
    out.push_back({SweepGroup::peakAmplitude,
                   name,
                   point,
                   {name + "." + point + ".peak", "m"},
                   [name, point](const Json& doc) {
                     const Json& r = analysisNamed(doc, name).at("response");
                     const std::string what = "response of " + point;
                     return required(required(r, point, what), "peak", what)
                         .at("amplitude_m")
                         .get<double>();
                   }});
}

/// A base-motion analysis: over its frequencies, the largest transmissibility and relative
/// displacement of each point and the largest force the ground exerts (its frequencies are
/// the excitation's, not the model's).
void addBaseMotion(const Json& a, std::vector<SweepQuantity>& out) {
  const std::string name = a.at("name");
  const auto largest = [](const Json& values) {
    double top = 0;
    for (const Json& v : values) top = std::max(top, v.get<double>());
    return top;
  };
  for (const auto& entry : a.at("points").items())
    for (const auto& [field, label, unit] :
         {std::tuple<std::string, std::string, std::string>{"transmissibility",
                                                            "largest transmissibility", ""},
          {"relative_m", "largest relative displacement", "m"}}) {
      // Named copies for the lambda (clang 14, the fuzz build's, cannot capture a binding).
      const std::string point = entry.key(), key = field;
      if (!entry.value().contains(key)) continue;
      out.push_back({SweepGroup::extreme,
                     name,
                     point + " " + label,
                     {name + "." + point + "." + key + "_max", unit},
                     [name, point, key, largest](const Json& doc) {
                       const Json& points = analysisNamed(doc, name).at("points");
                       const std::string what = key + " of " + point;
                       return largest(required(required(points, point, what), key, what));
                     }});
    }
  if (a.contains("base_force_n"))
    out.push_back({SweepGroup::extreme,
                   name,
                   "largest base force",
                   {name + ".base_force_max", "N"},
                   [name, largest](const Json& doc) {
                     return largest(analysisNamed(doc, name).at("base_force_n"));
                   }});
}

}  // namespace

std::vector<SweepQuantity> sweepQuantities(const std::vector<Json>& runDocs) {
  std::vector<SweepQuantity> out;
  for (const Json& a : runDocs.at(0).at("analyses")) {
    if (a.contains("reactions")) addStatic(a, out);
    if (a.contains("second_order")) addSecondOrder(a, out);
    if (a.contains("load_factors")) addBuckling(a, runDocs, out);
    // A frequency response's and a base motion's frequencies are their excitation's, not
    // the model's.
    const bool excited = a.at("type") == analysisTypeName<FrequencyResponseSpec>() ||
                         a.at("type") == analysisTypeName<BaseMotionSpec>();
    if (a.contains("frequencies_hz") && !excited) addModal(a, out);
    if (a.at("type") == analysisTypeName<BaseMotionSpec>()) addBaseMotion(a, out);
    if (a.contains("maxima")) addTransient(a, out);
    if (a.contains("critical_speeds")) addCampbell(a, runDocs, out);
    if (a.contains("response") && a.at("type") == analysisTypeName<UnbalanceSpec>())
      addUnbalance(a, out);
  }
  const Json reported = runDocs.at(0).value("reported", Json::object());
  for (const auto& [name, value] : reported.items())
    out.push_back({SweepGroup::reported, "", name, {name, ""}, [name](const Json& doc) {
                     return required(required(doc, "reported", "reported values"), name,
                                     "reported value " + name)
                         .get<double>();
                   }});
  std::vector<std::pair<std::string, std::string>> checks;  // name, unit
  for (const Json& doc : runDocs)
    for (const Json& c : doc.at("checks")) {
      const std::string name = c.at("name");
      if (std::none_of(checks.begin(), checks.end(), [&](const auto& k) { return k.first == name; }))
        checks.emplace_back(name, c.value("unit", ""));
    }
  for (const auto& check : checks) {
    const std::string& name = check.first;  // a plain name: the lambdas below copy it
    out.push_back({SweepGroup::check, "", name, {"check." + name, check.second},
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
          row.push_back(std::monostate());
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
