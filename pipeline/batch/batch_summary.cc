#include "pipeline/batch/batch_summary.h"

#include <fmt/format.h>

#include <map>
#include <set>

#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string FormatValue(const json& v) {
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (v.is_number_float()) return fmt::format("{:.2f}", v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  return "";
}

std::string Row(const std::vector<std::string>& cells) {
  std::string line;
  for (size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + CsvField(cells[i]);
  return line + "\n";
}

// Measurement names in order of first appearance over the ok scans.
std::vector<std::string> MeasurementColumns(const std::vector<ScanOutcome>& outcomes) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const ScanOutcome& o : outcomes) {
    if (!o.measurements.is_object() || !o.measurements.contains("measurements")) continue;
    for (const json& m : o.measurements["measurements"]) {
      const std::string name = m.value("name", "");
      if (!name.empty() && seen.insert(name).second) names.push_back(name);
    }
  }
  return names;
}

}  // namespace

std::string ScanOutcome::failure_kind() const {
  if (!record) return "not_processed";
  return record->failure ? record->failure->kind : "";
}

std::string ScanOutcome::failure_message() const {
  if (!record) return "not processed: " + problem;
  return record->failure ? record->failure->message : "";
}

std::vector<ScanOutcome> CollectOutcomes(const std::vector<ScanEntry>& plan,
                                         const fs::path& out_dir, bool verify_hashes) {
  std::vector<ScanOutcome> outcomes;
  for (const ScanEntry& entry : plan) {
    ScanOutcome o{entry, out_dir / entry.id, std::nullopt, "", json()};
    o.record = ReadValidDoneRecord(o.folder, verify_hashes, &o.problem);
    if (o.ok()) {
      for (const OutputFile& f : o.record->outputs) {
        if (f.file != kMeasurementsFileName) continue;
        try {
          o.measurements = ReadJsonFile(o.folder / f.file);
        } catch (const InputError& e) {
          o.record.reset();
          o.problem = e.what();
        }
      }
    }
    outcomes.push_back(std::move(o));
  }
  return outcomes;
}

std::string SummaryCsv(const std::vector<ScanOutcome>& outcomes) {
  std::set<std::string> result_names;
  for (const ScanOutcome& o : outcomes) {
    if (!o.ok()) continue;
    for (const auto& [key, value] : o.record->results.items()) result_names.insert(key);
  }
  const std::vector<std::string> measurements = MeasurementColumns(outcomes);
  std::vector<std::string> header = {"scan_id", "status", "failure_kind"};
  header.insert(header.end(), result_names.begin(), result_names.end());
  for (const std::string& m : measurements) header.push_back(m + "_mm");
  header.push_back("flagged");
  std::string csv = Row(header);
  for (const ScanOutcome& o : outcomes) {
    std::vector<std::string> cells = {o.entry.id, o.ok() ? "ok" : "failed", o.failure_kind()};
    std::map<std::string, std::string> values;
    std::string flagged;
    if (o.ok()) {
      for (const auto& [key, value] : o.record->results.items()) values[key] = FormatValue(value);
      if (o.measurements.is_object() && o.measurements.contains("measurements")) {
        for (const json& m : o.measurements["measurements"]) {
          const std::string name = m.value("name", "");
          if (m.contains("value_mm")) values[name + "_mm"] = FormatValue(m["value_mm"]);
          if (m.contains("flags") && m["flags"].is_array() && !m["flags"].empty()) {
            flagged += (flagged.empty() ? "" : ";") + name;
          }
        }
      }
    }
    for (size_t i = 3; i + 1 < header.size(); ++i) cells.push_back(values[header[i]]);
    cells.push_back(flagged);
    csv += Row(cells);
  }
  return csv;
}

std::string FailuresCsv(const std::vector<ScanOutcome>& outcomes) {
  std::string csv = Row({"scan_id", "input", "kind", "exit_code", "signal", "message"});
  for (const ScanOutcome& o : outcomes) {
    if (o.ok()) continue;
    const ScanFailure* f = o.record && o.record->failure ? &*o.record->failure : nullptr;
    csv += Row({o.entry.id, o.entry.path.string(), o.failure_kind(),
                f && f->exit_code >= 0 ? std::to_string(f->exit_code) : "",
                f && f->signal ? std::to_string(f->signal) : "", o.failure_message()});
  }
  return csv;
}

std::string TimingsCsv(const std::vector<ScanOutcome>& outcomes) {
  std::vector<std::string> steps;
  std::set<std::string> seen;
  for (const ScanOutcome& o : outcomes) {
    if (!o.record) continue;
    for (const json& s : o.record->steps) {
      const std::string name = s.value("name", "");
      if (!name.empty() && seen.insert(name).second) steps.push_back(name);
    }
  }
  std::vector<std::string> header = {"scan_id", "status",   "time_s",    "worker_wall_s",
                                     "user_s",  "system_s", "max_rss_mb"};
  for (const std::string& s : steps) header.push_back(s + "_s");
  std::string csv = Row(header);
  auto number = [](const json& j, const char* key, const char* format) {
    return j.is_object() && j.contains(key) && j[key].is_number()
               ? fmt::format(fmt::runtime(format), j[key].get<double>())
               : std::string();
  };
  for (const ScanOutcome& o : outcomes) {
    if (!o.record) {
      csv += Row({o.entry.id, "not_processed"});
      continue;
    }
    const json& w = o.record->worker;
    std::vector<std::string> cells = {o.entry.id,
                                      o.record->status,
                                      fmt::format("{:.3f}", o.record->time_s),
                                      number(w, "wall_s", "{:.3f}"),
                                      number(w, "user_s", "{:.3f}"),
                                      number(w, "system_s", "{:.3f}"),
                                      number(w, "max_rss_mb", "{:.1f}")};
    for (const std::string& step : steps) {
      std::string cell;
      for (const json& s : o.record->steps) {
        if (s.value("name", "") == step) cell = number(s, "time_s", "{:.3f}");
      }
      cells.push_back(cell);
    }
    csv += Row(cells);
  }
  return csv;
}

int BatchCounts::ExitCode() const {
  if (failed == 0 && not_processed == 0) return 0;
  return (not_processed == 0 && failed == input_errors) ? 1 : 2;
}

BatchCounts CountOutcomes(const std::vector<ScanOutcome>& outcomes) {
  BatchCounts c;
  for (const ScanOutcome& o : outcomes) {
    ++c.planned;
    if (o.ok()) {
      ++c.ok;
    } else if (!o.record) {
      ++c.not_processed;
    } else {
      ++c.failed;
      if (o.failure_kind() == "input_error") ++c.input_errors;
    }
  }
  return c;
}

}  // namespace bespoke
