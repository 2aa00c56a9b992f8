#include "eval/accuracy/reference_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include "scanners/core/errors.h"

namespace bespoke {
namespace fs = std::filesystem;

namespace {

std::string Joined(const std::set<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// The header's columns; InputError for a missing required column or a value
// column in another unit.
CsvColumns Columns(const CsvRecord& header, const fs::path& file) {
  const CsvColumns columns(header);
  if (!columns.Has("value_mm")) {
    for (const auto& [name, index] : columns.index()) {
      if (name == "value") {
        throw InputError(file,
                         "the column 'value' does not say its unit: give the values in "
                         "millimetres in a column named value_mm");
      }
      if (name.rfind("value_", 0) == 0) {
        throw InputError(file, "the column '" + name + "' is in " + name.substr(6) +
                                   ": give the values in millimetres in a column named value_mm");
      }
    }
  }
  for (const char* required : {"subject", "measurement", "value_mm"}) {
    if (!columns.Has(required)) {
      throw InputError(file, "line " + std::to_string(header.line) +
                                 ": the header must name the columns subject, measurement and "
                                 "value_mm (optional: method, unit); '" +
                                 required + "' is missing");
    }
  }
  return columns;
}

// The method compared: `chosen`, or the file's only one; InputError when the
// file has several and none is chosen, or the chosen one is absent.
std::string ChooseMethod(const std::vector<CsvRecord>& records, const CsvColumns& columns,
                         const std::string& chosen, const fs::path& file) {
  std::set<std::string> methods;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const std::string m = columns.Field(records[r], "method");
    if (!m.empty()) methods.insert(m);
  }
  if (!chosen.empty() && !methods.count(chosen)) {
    throw InputError(file, "no row has the method '" + chosen +
                               "' (methods: " + (methods.empty() ? "none" : Joined(methods)) + ")");
  }
  if (chosen.empty() && methods.size() > 1) {
    throw InputError(file, "holds values of several methods (" + Joined(methods) +
                               "); choose the one to compare with --method");
  }
  return chosen.empty() && !methods.empty() ? *methods.begin() : chosen;
}

// The value of a cell in mm, or the reason it is not one.
bool ParseMillimetres(const std::string& text, double* value, std::string* reason) {
  const std::string t = TrimBlanks(text);
  const char* end = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(t.data(), end, *value);
  if (t.empty() || ec != std::errc() || ptr != end || !std::isfinite(*value)) {
    *reason = "value '" + t + "' is not a number (millimetres, '.' as the decimal point)";
    return false;
  }
  if (*value <= 0) {
    *reason = "value " + t + " is not a positive length";
    return false;
  }
  return true;
}

// What is remembered across rows.
struct RowState {
  std::map<std::pair<std::string, std::string>, std::size_t> first;  // -> index in values
  std::set<std::pair<std::string, std::string>> conflicting;
  std::map<std::string, std::size_t> mapped_index;  // their name (lower) -> mapped_names index
};

// The catalogue measurement `their` stands for; "" with `reason` set when none.
std::string ResolveName(const std::string& their, const ReferenceTableOptions& options,
                        const Catalogue& catalogue, RowState* state, ReferenceTable* table,
                        std::string* reason) {
  const std::optional<NameMapEntry> mapped =
      options.names ? options.names->Find(their) : std::nullopt;
  if (mapped) {
    const auto [it, added] =
        state->mapped_index.emplace(AsciiLower(mapped->their_name), table->mapped_names.size());
    if (added)
      table->mapped_names.push_back({mapped->their_name, mapped->measurement, mapped->note, 0});
    ++table->mapped_names[it->second].rows;
    if (mapped->measurement.empty()) {
      *reason =
          "no Bespoke counterpart (name map " + options.names->source + ": " + mapped->note + ")";
    }
    return mapped->measurement;
  }
  if (catalogue.HasMeasurement(AsciiLower(their))) return AsciiLower(their);
  *reason = their.empty()   ? "no measurement name"
            : options.names ? "unknown measurement: not in the catalogue nor in the name map " +
                                  options.names->source
                            : "unknown measurement: not in the catalogue (another system's names "
                              "need --names)";
  return "";
}

// Why a row of a known measurement is left out before its value is read; "" when it is not.
std::string RowProblem(const std::string& subject, const std::string& method,
                       const std::string& unit, const std::string& compared_method) {
  if (subject.empty()) return "no subject";
  if (method != compared_method) {
    return "method '" + method + "', not the one compared ('" + compared_method + "')";
  }
  if (!unit.empty() && AsciiLower(unit) != "mm") return "unit '" + unit + "': give the value in mm";
  return "";
}

// Adds a checked value, or says why it is not added: the same subject and
// measurement again (a duplicate, or a conflict that leaves both out).
bool AddValue(ReferenceValue value, const std::string& text, RowState* state, ReferenceTable* table,
              std::string* reason) {
  const auto key = std::make_pair(value.subject, value.measurement);
  const auto it = state->first.find(key);
  if (it == state->first.end()) {
    state->first[key] = table->values.size();
    table->values.push_back(std::move(value));
    return true;
  }
  const ReferenceValue& earlier = table->values[it->second];
  if (value.value_mm == earlier.value_mm) {
    *reason = "duplicate of line " + std::to_string(earlier.line) + " (same value, counted once)";
  } else {
    state->conflicting.insert(key);
    *reason = "conflicts with line " + std::to_string(earlier.line) + " (" + text + " mm here, " +
              FormatNumber(earlier.value_mm, 2) + " mm there): both left out";
  }
  return false;
}

// Moves the values whose subject and measurement met a conflicting row into
// `not_compared`, and lists the subjects of the rest.
void DropConflicts(const RowState& state, const std::string& name, ReferenceTable* table) {
  std::vector<ReferenceValue> kept;
  for (ReferenceValue& v : table->values) {
    if (state.conflicting.count({v.subject, v.measurement})) {
      table->not_compared.push_back(
          {v.subject, v.measurement, name + " line " + std::to_string(v.line),
           "conflicts with a later row for the same subject and measurement: both left out"});
    } else {
      kept.push_back(std::move(v));
    }
  }
  table->values = std::move(kept);
  for (const ReferenceValue& v : table->values) {
    if (std::find(table->subjects.begin(), table->subjects.end(), v.subject) ==
        table->subjects.end())
      table->subjects.push_back(v.subject);
  }
}

}  // namespace

ReferenceTable ReadReferenceTable(const ReferenceTableOptions& options, const fs::path& file,
                                  const Catalogue& catalogue) {
  const std::vector<CsvRecord> records = ReadCsvRecords(file);
  if (records.empty()) throw InputError(file, "empty reference table (no header line)");
  const CsvColumns columns = Columns(records[0], file);
  const auto field = [&](const CsvRecord& r, const char* name) { return columns.Field(r, name); };
  ReferenceTable table;
  table.file = file;
  if (columns.Has("method")) {
    table.method = ChooseMethod(records, columns, options.method, file);
  } else if (!options.method.empty()) {
    throw InputError(file,
                     "--method '" + options.method + "' given, but there is no method column");
  }
  const std::string name = file.filename().string();
  RowState state;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const CsvRecord& row = records[r];
    const std::string subject = field(row, "subject"), their = field(row, "measurement");
    const std::string unit = field(row, "unit"), method = field(row, "method");
    NotCompared skip{subject, their, name + " line " + std::to_string(row.line), ""};
    ReferenceValue value{subject,
                         ResolveName(their, options, catalogue, &state, &table, &skip.reason), 0,
                         method.empty() ? table.method : method, row.line};
    if (skip.reason.empty()) skip.reason = RowProblem(subject, value.method, unit, table.method);
    if (skip.reason.empty() &&
        ParseMillimetres(field(row, "value_mm"), &value.value_mm, &skip.reason) &&
        AddValue(value, field(row, "value_mm"), &state, &table, &skip.reason)) {
      continue;
    }
    table.not_compared.push_back(std::move(skip));
  }
  DropConflicts(state, name, &table);
  return table;
}

}  // namespace bespoke
