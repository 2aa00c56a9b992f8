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
      "<h2>Targets (issue "
      "5)</h2>\n<table><tr><th>target</th><th>measured</th><th>verdict</th></tr>\n";
  html += "<tr><td>every measurement passes ISO 20685-1</td><td>" + std::to_string(s.passed) +
          " of " + std::to_string(judged_total) + " pass, " + std::to_string(s.failed) + " fail, " +
          std::to_string(s.not_judged) + " not judged (n &lt; 2)</td>" +
          Verdict(judged_total > 0 && s.passed == judged_total ? "met" : "missed") + "</tr>\n";
  html += "<tr><td>MAE of large girths &le; " + Num(report.targets.large_girth_mae_mm, 0) +
          " mm</td><td>" + Num(s.large_girth_mae_mm, 2) + " mm</td>" +
          Verdict(s.large_girth_mae_mm <= report.targets.large_girth_mae_mm ? "met" : "missed") +
          "</tr>\n";
  html +=
      "<tr><td>median landmark error &le; " + Num(report.targets.median_landmark_error_mm, 0) +
      " mm</td><td>" + Num(s.median_landmark_error_mm, 2) + " mm</td>" +
      Verdict(s.median_landmark_error_mm <= report.targets.median_landmark_error_mm ? "met"
                                                                                    : "missed") +
      "</tr>\n";
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
  return html + "</table>\n";
}

std::string MeasurementTable(const AccuracyReport& report, const std::vector<std::string>& plots) {
  std::string html =
      "<h2>Measurements: ISO 20685-1</h2>\n<p>Error = measured &minus; truth (mm). Pass when the "
      "95 % "
      "confidence interval of the mean error (Student t, n &minus; 1 degrees of freedom) lies "
      "within "
      "&plusmn;limit. Numbers (#) are the x positions in the error-distribution charts.</p>\n"
      "<table><tr><th>#</th><th>measurement</th><th>kind</th><th>ISO class</th><th>limit "
      "(mm)</th><th>n</th>"
      "<th>missing</th><th>flagged</th><th>bias (mm)</th><th>SD (mm)</th><th>95 % CI of the mean "
      "(mm)</th>"
      "<th>MAE (mm)</th><th>max |error| (mm)</th><th>verdict</th><th>plot</th></tr>\n";
  // Charts number the measurements within their class.
  std::map<IsoClass, int> counter;
  for (const MeasurementSummary& m : report.summary.measurements) {
    const ErrorStats& s = m.stats;
    const int number = m.differences_mm.empty() ? 0 : ++counter[m.iso_class];
    const std::string hist = "plots/hist_" + m.name + ".png";
    const bool has_hist = std::find(plots.begin(), plots.end(), hist) != plots.end();
    html += "<tr>" + Td(number ? std::to_string(number) : "") + Td(XmlEscape(m.name)) +
            Td(XmlEscape(m.kind)) + Td(ToString(m.iso_class)) + Td(Num(m.tolerance_mm, 0)) +
            Td(std::to_string(s.n)) + Td(std::to_string(m.missing)) +
            Td(std::to_string(m.flagged)) + Td(Num(s.mean_mm, 2)) + Td(Num(s.sd_mm, 2)) +
            Td("[" + Num(s.ci_low_mm, 2) + ", " + Num(s.ci_high_mm, 2) + "]") +
            Td(Num(s.mae_mm, 2)) + Td(Num(s.max_abs_mm, 2)) + Verdict(ToString(m.verdict)) +
            Td(has_hist ? "<a href=\"" + XmlEscape(hist) + "\">histogram</a>" : "") + "</tr>\n";
  }
  return html + "</table>\n";
}

std::string LandmarkTable(const AccuracyReport& report) {
  const std::string& frame = report.summary.landmark_frame;
  std::string html =
      "<h2>Landmarks</h2>\n<p>Error = 3-D distance (mm) between the found and the true datum "
      "point, compared in the " +
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
      ".na{background:#eee}img{max-width:100%}pre{background:#f6f6f6;padding:1em}</style></"
      "head><body>\n";
  html += "<h1>" + XmlEscape(report.title) + "</h1>\n<p>Created " + XmlEscape(report.created_utc) +
          "; " + std::to_string(report.summary.subjects) + " subjects compared, " +
          std::to_string(report.failures.size()) +
          " failed. Tables: <a href=\"summary.csv\">summary.csv</a>, "
          "<a href=\"measurements.csv\">measurements.csv</a>, <a "
          "href=\"landmarks.csv\">landmarks.csv</a>, "
          "<a href=\"landmark_errors.csv\">landmark_errors.csv</a>" +
          (report.posture ? ", <a href=\"posture.csv\">posture.csv</a>" : "") +
          ", <a href=\"report.json\">report.json</a>.</p>\n";
  html += Targets(report);
  for (const std::string& plot : plots) {
    if (plot.rfind("plots/errors_", 0) == 0) html += Image(plot);
  }
  html += MeasurementTable(report, plots);
  html += LandmarkTable(report);
  if (std::find(plots.begin(), plots.end(), "plots/landmarks.png") != plots.end()) {
    html += Image("plots/landmarks.png");
  }
  if (report.posture) {
    html += PostureTable(*report.posture);
    if (std::find(plots.begin(), plots.end(), "plots/posture.png") != plots.end()) {
      html += Image("plots/posture.png");
    }
  }
  if (!report.failures.empty()) {
    html +=
        "<h2>Subjects that "
        "failed</h2>\n<table><tr><th>subject</th><th>stage</th><th>error</th></tr>\n";
    for (const SubjectFailure& f : report.failures) {
      html += "<tr><td>" + XmlEscape(f.subject) + "</td><td>" + XmlEscape(f.stage) + "</td><td>" +
              XmlEscape(f.error) + "</td></tr>\n";
    }
    html += "</table>\n";
  }
  html +=
      "<h2>Settings</h2>\n<pre>" + XmlEscape(report.settings.dump(2)) + "</pre>\n</body></html>\n";
  return html;
}

}  // namespace bespoke
