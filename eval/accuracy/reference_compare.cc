#include "eval/accuracy/reference_compare.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "eval/accuracy/compare.h"

namespace bespoke {
using nlohmann::json;

namespace {

// The subject of a scan named `stem`, or "".
std::string SubjectOf(const std::string& stem, const std::set<std::string>& subjects) {
  if (subjects.count(stem)) return stem;
  const std::size_t underscore = stem.rfind('_');
  if (underscore == std::string::npos || underscore + 1 == stem.size()) return "";
  const std::string k = stem.substr(underscore + 1);
  if (!std::all_of(k.begin(), k.end(), [](char c) { return c >= '0' && c <= '9'; })) return "";
  const std::string subject = stem.substr(0, underscore);
  return subjects.count(subject) ? subject : "";
}

// The reference document of one subject (docs/contracts.md layout, values only).
json ReferenceDocument(const std::vector<const ReferenceValue*>& values,
                       const Catalogue& catalogue) {
  json measurements = json::array();
  for (const ReferenceValue* v : values) {
    measurements.push_back({{"name", v->measurement},
                            {"kind", ToString(catalogue.Measurement(v->measurement).kind)},
                            {"value_mm", v->value_mm}});
  }
  return {{"format", "bespoke-measurements"}, {"units", "mm"}, {"measurements", measurements}};
}

// Every finite value of `name` in the scans' documents, and their flags.
std::vector<double> ScanValues(const std::vector<const ScanMeasurement*>& scans,
                               const std::string& name, std::set<std::string>* flags) {
  std::vector<double> values;
  for (const ScanMeasurement* s : scans) {
    for (const json& m : s->measurements.value("measurements", json::array())) {
      if (!m.is_object() || m.value("name", "") != name) continue;
      if (m.contains("value_mm") && m["value_mm"].is_number() &&
          std::isfinite(m["value_mm"].get<double>()))
        values.push_back(m["value_mm"].get<double>());
      for (const json& f : m.value("flags", json::array()))
        if (f.is_string()) flags->insert(f.get<std::string>());
    }
  }
  return values;
}

// The subject's measured document: per reference measurement the mean of its
// scans' values (none: no value, counted missing) and their flags; the
// per-scan values go to `repeated`.
json MeasuredDocument(const std::vector<const ReferenceValue*>& values,
                      const std::vector<const ScanMeasurement*>& scans,
                      std::map<std::string, std::vector<std::vector<double>>>* repeated) {
  json measurements = json::array();
  for (const ReferenceValue* v : values) {
    std::set<std::string> flags;
    const std::vector<double> scan_values = ScanValues(scans, v->measurement, &flags);
    json entry = {{"name", v->measurement}, {"flags", flags}};
    if (!scan_values.empty()) {
      double sum = 0;
      for (double x : scan_values) sum += x;
      entry["value_mm"] = sum / static_cast<double>(scan_values.size());
    }
    (*repeated)[v->measurement].push_back(scan_values);
    measurements.push_back(entry);
  }
  return {{"format", "bespoke-measurements"}, {"units", "mm"}, {"measurements", measurements}};
}

// Failed scans: a failure of the subject when none was measured, else not compared.
void RecordFailedScans(const std::string& subject,
                       const std::vector<const ScanMeasurement*>& failed, bool any_measured,
                       AccuracyReport* report) {
  if (failed.empty()) return;
  if (any_measured) {
    for (const ScanMeasurement* s : failed) {
      report->not_compared.push_back({subject, "", "scan " + s->scan,
                                      "failed to measure (" + s->failure_kind +
                                          "): " + s->failure_message +
                                          "; the subject's other scans are compared"});
    }
    return;
  }
  std::string error;
  for (const ScanMeasurement* s : failed)
    error += (error.empty() ? "" : "; ") + s->scan + ": " + s->failure_message;
  report->failures.push_back({subject, failed.front()->failure_kind, error});
}

std::vector<RepeatabilityRow> Repeatability(
    const std::map<std::string, std::vector<std::vector<double>>>& repeated,
    const Catalogue& catalogue) {
  std::vector<RepeatabilityRow> rows;
  for (const MeasurementDef& def : catalogue.measurements()) {
    const auto it = repeated.find(def.name);
    if (it == repeated.end()) continue;
    RepeatabilityRow row{def.name, SummarizeRepeatability(it->second)};
    if (row.stats.subjects > 0) rows.push_back(row);
  }
  return rows;
}

}  // namespace

ScanMatch MatchScans(const std::vector<std::string>& subjects,
                     const std::vector<ScanEntry>& scans) {
  const std::set<std::string> known(subjects.begin(), subjects.end());
  std::map<std::string, std::vector<ScanEntry>> by_subject;
  ScanMatch match;
  for (const ScanEntry& scan : scans) {
    const std::string file = scan.path.filename().string();
    const std::string subject = SubjectOf(scan.path.stem().string(), known);
    if (subject.empty()) {
      match.not_compared.push_back({"", "", "scan " + file,
                                    "no subject of the reference table is called '" +
                                        scan.path.stem().string() +
                                        "' (repeated scans: SUBJECT_1, SUBJECT_2, ...)"});
    } else {
      by_subject[subject].push_back(scan);
    }
  }
  for (const std::string& subject : subjects) {
    std::vector<ScanEntry>& mine = by_subject[subject];
    if (mine.empty()) {
      match.not_compared.push_back({subject, "", "scans folder",
                                    "no scan " + subject + ".<ext> or " + subject +
                                        "_<k>.<ext> for this subject of the reference table"});
    }
    std::sort(mine.begin(), mine.end(), [](const ScanEntry& a, const ScanEntry& b) {
      return a.path.filename() < b.path.filename();
    });
    for (const ScanEntry& scan : mine) match.scans.push_back({subject, scan});
  }
  return match;
}

AccuracyReport CompareWithReference(const ReferenceTable& reference,
                                    const std::vector<ScanMeasurement>& scans,
                                    const Catalogue& catalogue) {
  AccuracyReport report;
  report.reference_label = "reference";
  report.not_compared = reference.not_compared;
  report.mapped_names = reference.mapped_names;
  std::map<std::string, std::vector<std::vector<double>>> repeated;
  for (const std::string& subject : reference.subjects) {
    std::vector<const ReferenceValue*> values;
    for (const ReferenceValue& v : reference.values)
      if (v.subject == subject) values.push_back(&v);
    std::vector<const ScanMeasurement*> measured, failed;
    for (const ScanMeasurement& s : scans) {
      if (s.subject != subject) continue;
      (s.failure_kind.empty() && s.measurements.is_object() ? measured : failed).push_back(&s);
    }
    RecordFailedScans(subject, failed, !measured.empty(), &report);
    if (measured.empty()) continue;
    report.subjects.push_back(CompareDocuments(MeasuredDocument(values, measured, &repeated),
                                               ReferenceDocument(values, catalogue), subject));
  }
  report.summary = SummarizeAccuracy(report.subjects, catalogue);
  report.repeatability = Repeatability(repeated, catalogue);
  return report;
}

}  // namespace bespoke
