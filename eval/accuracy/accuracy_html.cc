// index.html of the accuracy report (accuracy_report.h).
#include <algorithm>
#include <cmath>
#include <map>

#include "eval/accuracy/accuracy_report.h"
#include "scanners/core/xml_escape.h"

namespace bespoke {
namespace {

std::string Num(double v, int digits = 1) {
  const std::string s = FormatNumber(v, digits);
  return s.empty() ? "&ndash;" : s;
}

std::string Verdict(const std::string& verdict) {
  const char* css = verdict == "pass" || verdict == "met" ? "pass"
                    : verdict == "n/a"                    ? "na"
                                                          : "fail";
  return std::string("<td class=\"") + css + "\">" + XmlEscape(verdict) + "</td>";
}

std::string Td(const std::string& s) { return "<td>" + s + "</td>"; }

std::string Targets(const AccuracyReport& report) {
  const AccuracySummary& s = report.summary;
  const int judged_total = static_cast<int>(s.measurements.size());
  std::string html =
      "<h2>Targets</h2>\n<table><tr><th>target</th><th>measured</th><th>verdict</th></tr>\n";
  html += "<tr><td>every measurement passes ISO 20685-1</td><td>" + std::to_string(s.passed) +
          " of " + std::to_string(judged_total) + " pass, " + std::to_string(s.failed) + " fail, " +
          std::to_string(s.not_judged) + " not judged (n &lt; 2)</td>" +
          Verdict(judged_total > 0 && s.passed == judged_total ? "met" : "missed") + "</tr>\n";
  html += "<tr><td>MAE of large girths &le; " + Num(report.targets.large_girth_mae_mm, 0) +
          " mm</td><td>" + Num(s.large_girth_mae_mm, 2) + " mm</td>" +
          Verdict(s.large_girth_mae_mm <= report.targets.large_girth_mae_mm ? "met" : "missed") +
          "</tr>\n";
  if (!s.landmarks.empty()) {
    html +=
        "<tr><td>median landmark error &le; " + Num(report.targets.median_landmark_error_mm, 0) +
        " mm</td><td>" + Num(s.median_landmark_error_mm, 2) + " mm</td>" +
        Verdict(s.median_landmark_error_mm <= report.targets.median_landmark_error_mm ? "met"
                                                                                      : "missed") +
        "</tr>\n";
  }
  if (report.posture) {
    const PostureComparison& p = *report.posture;
    html += "<tr><td>posture: every length of the " + XmlEscape(p.pose_b) + " within " +
            Num(p.tolerance_mm, 0) + " mm of the " + XmlEscape(p.pose_a) + "</td><td>" +
            (p.error.empty()
                 ? std::to_string(p.passed) + " of " + std::to_string(p.judged) +
                       " lengths; largest difference " + Num(p.max_abs_difference_mm, 2) + " mm"
                 : "did not run: " + XmlEscape(p.error)) +
            "</td>" + Verdict(p.pass() ? "met" : "missed") + "</tr>\n";
  }
  if (!report.posture_pairs.empty()) {
    const PostureSetSummary s = SummarizePostures(report.posture_pairs);
    html += "<tr><td>posture: every length within " + Num(report.posture_pairs[0].tolerance_mm, 0) +
            " mm and every girth within its ISO 20685-1 limit of the same body's " +
            XmlEscape(s.reference) + " value</td><td>" + XmlEscape(s.Headline()) + "</td>" +
            Verdict(s.pairs > 0 && s.held == s.pairs ? "met" : "missed") + "</tr>\n";
  }
  return html + "</table>\n";
}

// A link to `file` labelled `text` when `plots` holds it, else "".
std::string PlotLink(const std::vector<std::string>& plots, const std::string& file,
                     const std::string& text) {
  if (std::find(plots.begin(), plots.end(), file) == plots.end()) return "";
  return "<a href=\"" + XmlEscape(file) + "\">" + text + "</a>";
}

std::string MeasurementTable(const AccuracyReport& report, const std::vector<std::string>& plots) {
  const std::string label = XmlEscape(report.reference_label);
  std::string html =
      "<h2>Measurements: ISO 20685-1</h2>\n<p>Error = measured &minus; " + label +
      " (mm). Pass when the 95 % confidence interval of the mean error (Student t, n &minus; 1 "
      "degrees of freedom) lies within &plusmn;limit. Limits of agreement (Bland-Altman): bias "
      "&plusmn; 1.96 SD, the range that 95 % of single differences fall in. Numbers (#) are the x "
      "positions in the error-distribution charts.</p>\n"
      "<table><tr><th>#</th><th>measurement</th><th>kind</th><th>ISO class</th><th>limit "
      "(mm)</th><th>n</th><th>missing</th><th>flagged</th><th>bias (mm)</th><th>SD (mm)</th>"
      "<th>95 % CI of the mean (mm)</th><th>limits of agreement (mm)</th><th>MAE (mm)</th>"
      "<th>max |error| (mm)</th><th>verdict</th><th>plots</th></tr>\n";
  // Charts number the measurements within their class.
  std::map<IsoClass, int> counter;
  for (const MeasurementSummary& m : report.summary.measurements) {
    const ErrorStats& s = m.stats;
    const int number = m.differences_mm.empty() ? 0 : ++counter[m.iso_class];
    std::string links = PlotLink(plots, "plots/hist_" + m.name + ".png", "histogram");
    const std::string bland_altman =
        PlotLink(plots, "plots/bland_altman_" + m.name + ".png", "Bland-Altman");
    if (!bland_altman.empty()) links += (links.empty() ? "" : ", ") + bland_altman;
    html += "<tr>" + Td(number ? std::to_string(number) : "") + Td(XmlEscape(m.name)) +
            Td(XmlEscape(m.kind)) + Td(ToString(m.iso_class)) + Td(Num(m.tolerance_mm, 0)) +
            Td(std::to_string(s.n)) + Td(std::to_string(m.missing)) +
            Td(std::to_string(m.flagged)) + Td(Num(s.mean_mm, 2)) + Td(Num(s.sd_mm, 2)) +
            Td("[" + Num(s.ci_low_mm, 2) + ", " + Num(s.ci_high_mm, 2) + "]") +
            Td("[" + Num(s.loa_low_mm, 2) + ", " + Num(s.loa_high_mm, 2) + "]") +
            Td(Num(s.mae_mm, 2)) + Td(Num(s.max_abs_mm, 2)) + Verdict(ToString(m.verdict)) +
            Td(links) + "</tr>\n";
  }
  return html + "</table>\n";
}

std::string RepeatabilityTable(const std::vector<RepeatabilityRow>& rows) {
  std::string html =
      "<h2>Repeatability</h2>\n<p>From the subjects scanned more than once. Within-subject SD: "
      "the pooled SD of one subject's repeated values; repeatability coefficient: 1.96 &times; "
      "&radic;2 &times; that SD, the difference two scans of one subject stay within for 95 % of "
      "pairs. Per-scan values: <a href=\"scans/summary.csv\">scans/summary.csv</a>.</p>\n"
      "<table><tr><th>measurement</th><th>subjects</th><th>scans</th><th>within-subject SD "
      "(mm)</th><th>repeatability coefficient (mm)</th></tr>\n";
  for (const RepeatabilityRow& r : rows) {
    html += "<tr>" + Td(XmlEscape(r.name)) + Td(std::to_string(r.stats.subjects)) +
            Td(std::to_string(r.stats.values)) + Td(Num(r.stats.within_sd_mm, 2)) +
            Td(Num(r.stats.coefficient_mm, 2)) + "</tr>\n";
  }
  return html + "</table>\n";
}

// Rows of plain text cells under `heading` (nothing when `rows` is empty).
std::string TextTable(const std::string& heading, const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows) {
  if (rows.empty()) return "";
  std::string html = "<h2>" + heading + "</h2>\n<table class=\"text\"><tr>";
  for (const std::string& h : header) html += "<th>" + XmlEscape(h) + "</th>";
  html += "</tr>\n";
  for (const std::vector<std::string>& row : rows) {
    html += "<tr>";
    for (const std::string& cell : row) html += Td(XmlEscape(cell));
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

std::string LandmarkTable(const AccuracyReport& report) {
  const std::string& frame = report.summary.landmark_frame;
  std::string html =
      "<h2>Landmarks</h2>\n<p>Error = 3-D distance (mm) between the found and the true datum "
      "point (for a point defined by a level, calf and thigh, the height's difference), "
      "compared in the " +
      XmlEscape(frame) + " frame" +
      (frame == "scanner" ? " (the found points mapped back through the cleaning's "
                            "body_from_scanner, so the body frame's own error is not counted)"
                          : "") +
      ".</p>\n<table><tr><th>#</th><th>landmark</th><th>n</th><th>missing</th>"
      "<th>median (mm)</th><th>mean (mm)</th><th>max (mm)</th></tr>\n";
  int number = 0;
  for (const LandmarkSummary& l : report.summary.landmarks) {
    html += "<tr>" + Td(std::to_string(++number)) + Td(XmlEscape(l.name)) +
            Td(std::to_string(l.n)) + Td(std::to_string(l.missing)) + Td(Num(l.median_mm)) +
            Td(Num(l.mean_mm)) + Td(Num(l.max_mm)) + "</tr>\n";
  }
  return html + "</table>\n";
}

std::string PostureTable(const PostureComparison& p) {
  std::string html = "<h2>Posture: " + XmlEscape(p.pose_a) + " (arms " + Num(p.arm_a_deg, 0) +
                     "&deg;) vs " + XmlEscape(p.pose_b) + " (arms " + Num(p.arm_b_deg, 0) +
                     "&deg;)</h2>\n";
  if (!p.error.empty())
    return html + "<p class=\"fail\">Did not run: " + XmlEscape(p.error) + "</p>\n";
  html +=
      "<p>The same body scanned and measured in both poses. Lengths are judged: |" +
      XmlEscape(p.pose_b) + " &minus; " + XmlEscape(p.pose_a) + "| &le; " + Num(p.tolerance_mm, 0) +
      " mm. The truth columns show how much the body itself changed between the poses. "
      "Numbers (#) are the x positions in the posture chart.</p>\n"
      "<table><tr><th>#</th><th>measurement</th><th>kind</th><th>measured A (mm)</th><th>measured "
      "B (mm)</th>"
      "<th>B &minus; A (mm)</th><th>truth A (mm)</th><th>truth B (mm)</th><th>verdict</th></tr>\n";
  int number = 0;
  for (const PostureRow& r : p.rows) {
    html += "<tr>" + Td(r.judged ? std::to_string(++number) : "") + Td(XmlEscape(r.name)) +
            Td(XmlEscape(r.kind)) + Td(Num(r.measured_a_mm)) + Td(Num(r.measured_b_mm)) +
            Td(Num(r.difference_mm)) + Td(Num(r.truth_a_mm)) + Td(Num(r.truth_b_mm)) +
            (r.judged ? Verdict(r.pass ? "pass" : "fail") : Td("shown only")) + "</tr>\n";
  }
  return html + "</table>\n";
}

// "3 / 4" (passed / judged) in a cell coloured by whether all passed.
std::string Fraction(int passed, int judged) {
  const std::string css = judged == 0 ? "na" : passed == judged ? "pass" : "fail";
  return "<td class=\"" + css + "\">" + std::to_string(passed) + " / " + std::to_string(judged) +
         "</td>";
}

// Per posture: pairs that hold, lengths and girths, the worst value; then a
// cell per subject (values within limit / judged, or why it did not run).
std::string PostureSetTable(const std::vector<PostureComparison>& pairs,
                            const PostureSetSummary& s) {
  std::vector<std::string> subjects;
  for (const PostureComparison& p : pairs) {
    if (std::find(subjects.begin(), subjects.end(), p.subject) == subjects.end())
      subjects.push_back(p.subject);
  }
  std::string html =
      "<table><tr><th>posture</th><th>pairs that hold</th><th>lengths within</th><th>girths "
      "within</th><th>worst (subject)</th><th>difference (mm)</th><th>limit (mm)</th>";
  for (const std::string& subject : subjects) html += "<th>" + XmlEscape(subject) + "</th>";
  html += "</tr>\n";
  for (const PostureSetRow& r : s.postures) {
    const std::string worst = r.worst_measurement.empty()
                                  ? ""
                                  : XmlEscape(r.worst_measurement + " (" + r.worst_subject + ")");
    html += "<tr>" + Td(XmlEscape(r.posture)) + Fraction(r.held, r.pairs) +
            Fraction(r.lengths_passed, r.lengths_judged) +
            Fraction(r.girths_passed, r.girths_judged) + Td(worst) +
            Td(r.worst_measurement.empty() ? "" : Num(r.worst_difference_mm, 1)) +
            Td(r.worst_measurement.empty() ? "" : Num(r.worst_limit_mm, 0));
    for (const std::string& subject : subjects) {
      const auto p = std::find_if(pairs.begin(), pairs.end(), [&](const PostureComparison& c) {
        return c.subject == subject && c.pose_b == r.posture;
      });
      if (p == pairs.end()) {
        html += Td("");
      } else if (!p->error.empty()) {
        html += "<td class=\"fail\">did not run</td>";
      } else {
        html += Fraction(p->passed, p->judged);
      }
    }
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

std::string PostureMeasurementTable(const PostureSetSummary& s) {
  std::string html =
      "<table><tr><th>measurement</th><th>kind</th><th>ISO class</th><th>limit (mm)</th>"
      "<th>pairs within limit</th><th>missing</th><th>largest |difference| (mm)</th><th>in "
      "pair</th><th>largest |truth difference| (mm)</th><th>pairs whose truth moved beyond the "
      "limit</th></tr>\n";
  for (const PostureMeasurementRow& m : s.measurements) {
    html += "<tr>" + Td(XmlEscape(m.name)) + Td(XmlEscape(m.kind)) + Td(XmlEscape(m.iso_class)) +
            Td(std::isfinite(m.limit_mm) ? Num(m.limit_mm, 0) : "shown only") +
            (m.judged > 0 ? Fraction(m.within, m.judged) : Td("")) + Td(std::to_string(m.missing)) +
            Td(Num(m.max_abs_difference_mm, 1)) +
            Td(m.max_subject.empty() ? "" : XmlEscape(m.max_subject + " " + m.max_posture)) +
            Td(Num(m.max_abs_truth_difference_mm, 1)) +
            Td(m.judged > 0 ? std::to_string(m.truth_beyond) : "") + "</tr>\n";
  }
  return html + "</table>\n";
}

std::string PostureTestSection(const std::vector<PostureComparison>& pairs) {
  const PostureSetSummary s = SummarizePostures(pairs);
  std::string html =
      "<h2>Posture test: each subject against itself in " + XmlEscape(s.reference) + "</h2>\n<p>" +
      XmlEscape(s.Headline()) +
      ". Every subject built, scanned and measured in the reference posture and in each listed "
      "one (same body, same scan seed); difference = posture &minus; reference. Judged: lengths "
      "along the surface within " +
      Num(pairs[0].tolerance_mm, 0) +
      " mm, girths within their ISO 20685-1 class limit (small 4 mm, large 9 mm); a value "
      "missing in either fails. Heights and the straight breadths are shown, not judged. A pair "
      "holds when every judged value does. Per pair and measurement, with both truths: <a "
      "href=\"posture.csv\">posture.csv</a>.</p>\n";
  html += PostureSetTable(pairs, s);
  html +=
      "<h3>Per measurement, over every pair that ran</h3>\n<p>The truth difference is how much "
      "the body itself changed between the postures (the exact measurements of both meshes).</p>\n";
  html += PostureMeasurementTable(s);
  std::vector<std::vector<std::string>> failed;
  for (const PostureComparison& p : pairs) {
    if (!p.error.empty()) failed.push_back({p.subject, p.pose_b, p.error});
  }
  return html +
         TextTable("Posture pairs that did not run", {"subject", "posture", "error"}, failed);
}

std::string TableLinks(const AccuracyReport& report) {
  std::vector<std::string> files = {"summary.csv", "measurements.csv"};
  if (!report.summary.landmarks.empty())
    files.insert(files.end(), {"landmarks.csv", "landmark_errors.csv"});
  if (report.posture || !report.posture_pairs.empty()) files.push_back("posture.csv");
  if (!report.repeatability.empty()) files.push_back("repeatability.csv");
  if (!report.not_compared.empty()) files.push_back("not_compared.csv");
  files.push_back("report.json");
  std::string links;
  for (const std::string& f : files)
    links += (links.empty() ? "" : ", ") + std::string("<a href=\"") + f + "\">" + f + "</a>";
  return links;
}

std::string Image(const std::string& file) {
  return "<figure><img src=\"" + XmlEscape(file) + "\" alt=\"" + XmlEscape(file) + "\"></figure>\n";
}

}  // namespace

std::string AccuracyHtml(const AccuracyReport& report, const std::vector<std::string>& plots) {
  std::string html =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + XmlEscape(report.title) +
      "</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:1400px}"
      "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
      "text-align:right}td:nth-child(-n+4),th{text-align:left}.pass{background:#dfd}.fail{"
      "background:#fdd}"
      ".na{background:#eee}table.text "
      "td{text-align:left}img{max-width:100%}pre{background:#f6f6f6;padding:1em}</style></"
      "head><body>\n";
  html += "<h1>" + XmlEscape(report.title) + "</h1>\n<p>Created " + XmlEscape(report.created_utc) +
          "; " + std::to_string(report.summary.subjects) + " subjects compared, " +
          std::to_string(report.failures.size()) + " failed. Tables: " + TableLinks(report) +
          ".</p>\n";
  html += Targets(report);
  for (const std::string& plot : plots) {
    if (plot.rfind("plots/errors_", 0) == 0) html += Image(plot);
  }
  html += MeasurementTable(report, plots);
  if (!report.repeatability.empty()) html += RepeatabilityTable(report.repeatability);
  if (!report.summary.landmarks.empty()) html += LandmarkTable(report);
  if (std::find(plots.begin(), plots.end(), "plots/landmarks.png") != plots.end()) {
    html += Image("plots/landmarks.png");
  }
  if (report.posture) {
    html += PostureTable(*report.posture);
    if (std::find(plots.begin(), plots.end(), "plots/posture.png") != plots.end()) {
      html += Image("plots/posture.png");
    }
  }
  if (!report.posture_pairs.empty()) html += PostureTestSection(report.posture_pairs);
  std::vector<std::vector<std::string>> failures, not_compared, mapped;
  for (const SubjectFailure& f : report.failures) failures.push_back({f.subject, f.stage, f.error});
  for (const NotCompared& n : report.not_compared)
    not_compared.push_back({n.subject, n.measurement, n.where, n.reason});
  for (const MappedName& m : report.mapped_names)
    mapped.push_back({m.their_name, m.measurement, std::to_string(m.rows), m.note});
  html += TextTable("Subjects that failed", {"subject", "stage", "error"}, failures);
  html += TextTable("Not compared", {"subject", "measurement", "where", "reason"}, not_compared);
  html += TextTable("Names mapped",
                    {"their name", "measurement", "rows", "how the definitions differ"}, mapped);
  html +=
      "<h2>Settings</h2>\n<pre>" + XmlEscape(report.settings.dump(2)) + "</pre>\n</body></html>\n";
  return html;
}

}  // namespace bespoke
