#pragma once
// One table of a record type's fields, from which its JSON line (results.jsonl, summary.json),
// its results.csv columns and its read-back are all made, so that a field is named once.
// Numbers that are not finite are written as the texts "nan", "inf" and "-inf" (JSON has no
// such numbers, and nlohmann::json would write null, which does not read back as a number);
// read_number takes both forms.
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "core/util/Format.hpp"

namespace vorodg {

/// A number as JSON: itself if finite, else "nan", "inf" or "-inf".
nlohmann::json number_json(double x);
/// A number written by number_json (or null, as older records wrote a non-finite number);
/// throws nlohmann::json::type_error for anything else.
double read_number(const nlohmann::json& j);

/// How a field appears in results.csv.
struct CsvFormat {
  bool listed = true;
  int digits = 6;             // significant digits of a number
  bool blank_if_nan = false;  // a non-finite number as an empty cell
  bool quoted = false;        // a text in double quotes (its own double quotes turned to ')
};
inline constexpr CsvFormat kNotInCsv{false, 0, false};

template <class Record>
struct RecordField {
  std::string name;
  std::function<nlohmann::json(const Record&)> get;
  std::function<void(Record&, const nlohmann::json&)> set = {};  // null: not read back
  CsvFormat csv = {};
  bool optional = false;  // absent from JSON when NaN (not measured), and NaN when absent
  bool in_json = true;    // false: a column of results.csv only (a setting of the scene)
  bool number = false;    // a double: written through number_json
  /// Where set, the field exists only where it holds: absent from JSON, an empty CSV cell, and
  /// not expected when read back.
  std::function<bool(const Record&)> when = {};
  /// false: older records may lack it; reading one leaves the record's default.
  bool required = true;

  bool holds(const Record& r) const { return !when || when(r); }
};

/// The names of the fields that are numbers in the JSON line (what a report can take statistics
/// of).
template <class Record>
std::vector<std::string> number_field_names(const std::vector<RecordField<Record>>& fields) {
  std::vector<std::string> names;
  for (const RecordField<Record>& f : fields)
    if (f.number && f.in_json) names.push_back(f.name);
  return names;
}

/// A member of the record: doubles through number_json, anything else as nlohmann::json
/// reads and writes it (integers, booleans, texts).
template <class Record, class T>
RecordField<Record> field(std::string name, T Record::*member, CsvFormat csv = {},
                          bool optional = false) {
  if constexpr (std::is_same_v<T, double>)
    return {std::move(name),
            [member](const Record& r) { return number_json(r.*member); },
            [member](Record& r, const nlohmann::json& j) { r.*member = read_number(j); },
            csv,
            optional,
            true,
            true};
  else
    return {std::move(name), [member](const Record& r) { return nlohmann::json(r.*member); },
            [member](Record& r, const nlohmann::json& j) { r.*member = j.get<T>(); }, csv,
            optional};
}

/// A column of results.csv that is not part of the record (the same for every run).
template <class Record>
RecordField<Record> csv_column(std::string name, nlohmann::json value, CsvFormat csv = {}) {
  return {std::move(name), [value](const Record&) { return value; }, nullptr, csv, false, false};
}

/// The fields every ensemble record (fracture, dynamics) starts with: its run's id, mesh block,
/// level, realization and seed. They are not read back: the run list gives them.
template <class Record>
std::vector<RecordField<Record>> run_id_fields() {
  return {{"id", [](const Record& r) { return nlohmann::json(r.run.id()); }},
          {"mesh", [](const Record& r) { return nlohmann::json(r.run.label); }},
          {"level", [](const Record& r) { return nlohmann::json(r.run.level); }},
          {"realization", [](const Record& r) { return nlohmann::json(r.run.realization); }},
          {"seed", [](const Record& r) { return nlohmann::json(r.run.seed); }, nullptr, kNotInCsv}};
}

/// A field's value as one CSV cell: numbers with the field's digits, booleans as 1 or 0.
std::string csv_cell(const nlohmann::json& value, const CsvFormat& format);

/// The record as one JSON object (optional fields left out when NaN).
template <class Record>
nlohmann::json record_json(const std::vector<RecordField<Record>>& fields, const Record& r) {
  nlohmann::json j = nlohmann::json::object();
  for (const RecordField<Record>& f : fields) {
    if (!f.in_json || !f.holds(r)) continue;
    nlohmann::json v = f.get(r);
    if (f.optional && v.is_string() && v.get<std::string>() == "nan") continue;
    j[f.name] = std::move(v);
  }
  return j;
}

/// Reads back what record_json wrote: every field that is not optional must be there.
template <class Record>
void read_record(const std::vector<RecordField<Record>>& fields, const nlohmann::json& j,
                 Record& r) {
  for (const RecordField<Record>& f : fields) {
    if (!f.set || !f.in_json) continue;
    if (j.contains(f.name))
      f.set(r, j.at(f.name));
    else if (f.optional)
      f.set(r, number_json(NAN));
    else if (f.required && !f.when)
      f.set(r, j.at(f.name));  // throws, naming the missing field
  }
}

/// The header line of results.csv: the listed fields' names.
template <class Record>
std::string csv_header(const std::vector<RecordField<Record>>& fields) {
  std::string line;
  for (const RecordField<Record>& f : fields)
    if (f.csv.listed) {
      if (!line.empty()) line += ',';
      line += f.name;
    }
  return line + "\n";
}

/// One row of results.csv.
template <class Record>
std::string csv_row(const std::vector<RecordField<Record>>& fields, const Record& r) {
  std::string line;
  bool first = true;
  for (const RecordField<Record>& f : fields)
    if (f.csv.listed) {
      if (!first) line += ',';
      if (f.holds(r)) line += csv_cell(f.get(r), f.csv);
      first = false;
    }
  return line + "\n";
}

/// The name of the first field that must be a number and is not finite ("" if none): a run
/// whose result overflowed is not a complete run (optional fields may be NaN: not measured).
template <class Record>
std::string non_finite_field(const std::vector<RecordField<Record>>& fields, const Record& r) {
  for (const RecordField<Record>& f : fields) {
    if (f.number && !f.optional && f.in_json && f.get(r).is_string()) return f.name;
  }
  return "";
}

/// A complete run whose result is not finite is not complete: marks it so, with a failure that
/// names the quantity. Returns true if it did.
template <class Record>
bool refuse_non_finite(const std::vector<RecordField<Record>>& fields, Record& r) {
  const std::string overflow = non_finite_field(fields, r);
  if (!r.complete || overflow.empty()) return false;
  r.complete = false;
  r.failure = overflow + " is not finite: the numbers overflowed (check the scene's scales)";
  return true;
}

}  // namespace vorodg
