#include "pipeline/batch/batch_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <ctime>
#include <map>
#include <numeric>

#include "pipeline/batch/batch_plan.h"
#include "pipeline/batch/done_record.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/json_io.h"
#include "scanners/core/xml_escape.h"
#include "scanners/render/plot.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

double ParseUtc(const std::string& text) {
  std::tm tm{};
  if (text.empty() || !strptime(text.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm)) return -1;
  return static_cast<double>(timegm(&tm));
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Measurement values by name over the ok scans, in column order.
std::vector<std::pair<std::string, std::vector<double>>> MeasurementValues(
    const std::vector<ScanOutcome>& outcomes) {
  std::vector<std::pair<std::string, std::vector<double>>> values;
  std::map<std::string, size_t> index;
  for (const ScanOutcome& o : outcomes) {
    if (!o.ok() || !o.measurements.is_object() || !o.measurements.contains("measurements"))
      continue;
    for (const json& m : o.measurements["measurements"]) {
      if (!m.contains("value_mm") || !m["value_mm"].is_number()) continue;
      const std::string name = m.value("name", "");
      if (!index.count(name)) {
        index[name] = values.size();
        values.push_back({name, {}});
      }
      values[index[name]].second.push_back(m["value_mm"].get<double>());
    }
  }
  return values;
}

std::string Histogram(const fs::path& results_dir, const std::string& name,
                      const std::string& title, const std::string& x_label,
                      const std::vector<double>& values) {
  Chart chart;
  chart.title = title;
  chart.x_label = x_label;
  chart.y_label = "scans";
  chart.width_px = 480;
  chart.height_px = 300;
  chart.series.push_back(HistogramSeries(values, std::clamp<int>(values.size() / 3, 5, 20), ""));
  const std::string file = "report/" + name + ".png";
  WriteChart(chart, results_dir / file);
  return "<figure><img src=\"" + XmlEscape(file) + "\" alt=\"" + XmlEscape(title) +
         "\"></figure>\n";
}

std::string Plots(const fs::path& results_dir, const BatchResultsInput& input) {
  static const std::vector<std::string> kMain = {
      "stature",    "bust_girth", "chest_girth", "waist_girth", "hip_girth",
      "neck_girth", "inside_leg", "arm_length",  "back_length", "thigh_girth"};
  const auto all = MeasurementValues(input.outcomes);
  std::vector<const std::pair<std::string, std::vector<double>>*> chosen;
  for (const std::string& name : kMain) {
    for (const auto& v : all)
      if (v.first == name) chosen.push_back(&v);
  }
  for (size_t i = 0; chosen.empty() && i < all.size() && i < 6; ++i) chosen.push_back(&all[i]);
  std::string html;
  for (const auto* v : chosen) {
    html += Histogram(results_dir, "hist_" + v->first, v->first, v->first + " (mm)", v->second);
  }
  std::vector<double> times, points;
  for (const ScanOutcome& o : input.outcomes) {
    if (!o.ok()) continue;
    times.push_back(o.record->time_s);
    const json& r = o.record->results;
    if (r.contains("points_cleaned") && r["points_cleaned"].is_number()) {
      points.push_back(r["points_cleaned"].get<double>());
    }
  }
  if (!times.empty())
    html += Histogram(results_dir, "hist_time", "time per scan", "time (s)", times);
  if (!points.empty()) {
    html += Histogram(results_dir, "hist_points", "points after cleaning", "points", points);
  }
  if (chosen.empty()) html += "<p>No measurements in this batch's results.</p>\n";
  return html;
}

std::string AttemptsSection(const BatchResultsInput& input, int* ran_total, double* span_s) {
  std::string html =
      "<table><tr><th>shard</th><th>label</th><th>host</th><th>started (UTC)</th>"
      "<th>status</th><th>exit</th><th>skipped (done before)</th><th>ran</th><th>wall (s)</th>"
      "<th>scans/min</th></tr>\n";
  double first = -1, last = -1;
  std::map<std::string, int> per_shard;
  for (const json& a : input.attempts) ++per_shard[a.value("shard", "")];
  for (const json& a : input.attempts) {
    std::string status = a.value("status", "");
    if (status == "running") {
      status = "did not finish (killed, lost, or still running); last seen " +
               a.value("updated_utc", a.value("started_utc", ""));
    }
    const int ran = a.value("ran", 0);
    const double wall = a.value("wall_s", 0.0);
    *ran_total += ran;
    const double start = ParseUtc(a.value("started_utc", ""));
    const double end = ParseUtc(a.value("finished_utc", a.value("updated_utc", "")));
    if (start >= 0 && (first < 0 || start < first)) first = start;
    if (end >= 0 && end > last) last = end;
    html += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{:.1f}</td><td>{}</td></tr>\n",
        XmlEscape(a.value("shard", "")), XmlEscape(a.value("label", "")),
        XmlEscape(a.value("host", "")), XmlEscape(a.value("started_utc", "")), XmlEscape(status),
        a.contains("exit_code") ? std::to_string(a.value("exit_code", 0)) : "",
        a.value("skipped", 0), ran, wall, wall > 0 ? fmt::format("{:.1f}", 60.0 * ran / wall) : "");
  }
  html += "</table>\n";
  int retried = 0;
  for (const auto& [shard, n] : per_shard) retried += n > 1 ? 1 : 0;
  html += fmt::format(
      "<p>{} attempt(s); {} shard(s) needed more than one attempt "
      "(interrupted or failed, then resumed/retried).</p>\n",
      input.attempts.size(), retried);
  *span_s = first >= 0 && last >= first ? last - first : 0;
  return html;
}

}  // namespace

std::string BatchReportHtml(const fs::path& results_dir, const BatchResultsInput& input,
                            const BatchCounts& counts) {
  CreateDirectories(results_dir / "report");
  std::string html = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" +
                     XmlEscape(input.title) +
                     "</title><style>body{font-family:sans-serif;margin:2em;max-width:1200px}"
                     "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;"
                     "padding:3px 8px;text-align:left;font-size:90%}th{background:#eee}"
                     ".failed{color:#a00}figure{display:inline-block;margin:4px}</style></head>"
                     "<body>\n<h1>" +
                     XmlEscape(input.title) + "</h1>\n";
  html += "<p>Generated " + UtcNow() + " by bespoke " +
          XmlEscape(BuildVersions().value("bespoke", "")) + ".</p>\n";
  std::map<std::string, int> kinds;
  for (const ScanOutcome& o : input.outcomes)
    if (!o.ok()) ++kinds[o.failure_kind()];
  html += fmt::format(
      "<h2>Counts</h2><table><tr><th>planned</th><th>ok</th><th>failed</th>"
      "<th>not processed</th></tr><tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
      "</tr></table>\n<p>Exit code {}.",
      counts.planned, counts.ok, counts.failed, counts.not_processed, counts.ExitCode());
  for (const auto& [kind, n] : kinds) html += fmt::format(" {}: {}.", XmlEscape(kind), n);
  html += "</p>\n";

  int ran = 0;
  double span = 0;
  const std::string attempts = AttemptsSection(input, &ran, &span);
  std::vector<double> times, rss;
  for (const ScanOutcome& o : input.outcomes) {
    if (!o.record) continue;
    times.push_back(o.record->time_s);
    if (o.record->worker.contains("max_rss_mb"))
      rss.push_back(o.record->worker["max_rss_mb"].get<double>());
  }
  html += "<h2>Throughput</h2>\n";
  html += fmt::format(
      "<p>{} scan(s) run over {:.1f} s from the first attempt's start to the last's "
      "end: <b>{}</b> scans per minute (wall clock, including any pause between "
      "attempts). Per scan: median {:.2f} s, mean {:.2f} s, max {:.2f} s; peak "
      "worker memory {:.0f} MB.</p>\n",
      ran, span, span > 0 ? fmt::format("{:.1f}", 60.0 * ran / span) : std::string("n/a"),
      Median(times),
      times.empty() ? 0.0 : std::accumulate(times.begin(), times.end(), 0.0) / times.size(),
      times.empty() ? 0.0 : *std::max_element(times.begin(), times.end()),
      rss.empty() ? 0.0 : *std::max_element(rss.begin(), rss.end()));
  html += "<h2>Attempts</h2>\n" + attempts;

  html += "<h2>Failures</h2>\n";
  if (counts.failed + counts.not_processed == 0)
    html += "<p>None.</p>\n";
  else
    html += "<table><tr><th>scan</th><th>input</th><th>kind</th><th>reason</th><th>log</th></tr>\n";
  for (const ScanOutcome& o : input.outcomes) {
    if (o.ok()) continue;
    const std::string folder = o.folder.lexically_relative(results_dir).generic_string();
    html += "<tr class=\"failed\"><td>" + XmlEscape(o.entry.id) + "</td><td>" +
            XmlEscape(o.entry.path.string()) + "</td><td>" + XmlEscape(o.failure_kind()) +
            "</td><td>" + XmlEscape(o.failure_message()) + "</td><td><a href=\"" +
            XmlEscape(folder + "/run.log") + "\">run.log</a></td></tr>\n";
  }
  if (counts.failed + counts.not_processed > 0) html += "</table>\n";

  html += "<h2>Distributions</h2>\n" + Plots(results_dir, input);

  html +=
      "<h2>Scans</h2>\n<table><tr><th>scan</th><th>status</th><th>time "
      "(s)</th><th>folder</th></tr>\n";
  for (const ScanOutcome& o : input.outcomes) {
    const std::string folder = o.folder.lexically_relative(results_dir).generic_string();
    html +=
        fmt::format("<tr{}><td>{}</td><td>{}</td><td>{}</td><td><a href=\"{}/\">{}</a></td></tr>\n",
                    o.ok() ? "" : " class=\"failed\"", XmlEscape(o.entry.id),
                    o.ok() ? "ok" : XmlEscape(o.failure_kind()),
                    o.record ? fmt::format("{:.2f}", o.record->time_s) : "", XmlEscape(folder),
                    XmlEscape(folder));
  }
  html += "</table>\n<h2>Settings</h2>\n<pre>" + XmlEscape(input.settings.dump(2)) +
          "</pre>\n</body></html>\n";
  return html;
}

BatchCounts WriteBatchResults(const fs::path& results_dir, const BatchResultsInput& input) {
  CreateDirectories(results_dir);
  std::error_code ec;
  fs::remove(results_dir / kBatchDoneFileName, ec);
  const BatchCounts counts = CountOutcomes(input.outcomes);
  WriteFileAtomically(results_dir / "summary.csv", SummaryCsv(input.outcomes));
  WriteFileAtomically(results_dir / "failures.csv", FailuresCsv(input.outcomes));
  WriteFileAtomically(results_dir / "timings.csv", TimingsCsv(input.outcomes));
  WriteFileAtomically(results_dir / "report.html", BatchReportHtml(results_dir, input, counts));
  WriteJsonFile(results_dir / kBatchDoneFileName,
                {{"format", "bespoke-batch-results"},
                 {"version", 1},
                 {"title", input.title},
                 {"planned", counts.planned},
                 {"ok", counts.ok},
                 {"failed", counts.failed},
                 {"not_processed", counts.not_processed},
                 {"exit_code", counts.ExitCode()},
                 {"generated_utc", UtcNow()},
                 {"versions", BuildVersions()},
                 {"settings", input.settings},
                 {"files", {"summary.csv", "failures.csv", "timings.csv", "report.html"}}});
  return counts;
}

}  // namespace bespoke
