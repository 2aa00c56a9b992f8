#include "eval/accuracy/accuracy_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "scanners/core/atomic_file.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A CSV cell: quoted when it holds a comma, quote or newline.
std::string Cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string Join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

json NumberOrNull(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

void WriteMeasurementsCsv(const AccuracyReport& report, const fs::path& file) {
  std::ostringstream out;
  const std::string& label = report.reference_label;
  out << "subject,measurement,kind," << label << "_mm,measured_mm,difference_mm,missing,flags,"
      << label << "_flags\n";
  for (const SubjectComparison& s : report.subjects) {
    for (const MeasurementDifference& d : s.measurements) {
      out << Cell(s.subject) << ',' << Cell(d.name) << ',' << d.kind << ','
          << FormatNumber(d.truth_mm) << ',' << FormatNumber(d.measured_mm) << ','
          << FormatNumber(d.difference_mm) << ',' << (d.missing ? 1 : 0) << ','
          << Cell(Join(d.flags, ";")) << ',' << Cell(Join(d.truth_flags, ";")) << '\n';
    }
  }
  WriteFileAtomically(file, out.str());
}

void WriteSummaryCsv(const AccuracyReport& report, const fs::path& file) {
  std::ostringstream out;
  out << "measurement,kind,iso_class,tolerance_mm,n,missing,flagged," << report.reference_label
      << "_flagged,bias_mm,sd_mm,ci_low_mm,ci_high_mm,loa_low_mm,loa_high_mm,mae_mm,max_abs_mm,"
         "median_abs_mm,verdict\n";
  for (const MeasurementSummary& m : report.summary.measurements) {
    const ErrorStats& s = m.stats;
    out << Cell(m.name) << ',' << m.kind << ',' << ToString(m.iso_class) << ','
        << FormatNumber(m.tolerance_mm, 0) << ',' << s.n << ',' << m.missing << ',' << m.flagged
        << ',' << m.truth_flagged << ',' << FormatNumber(s.mean_mm, 3) << ','
        << FormatNumber(s.sd_mm, 3) << ',' << FormatNumber(s.ci_low_mm, 3) << ','
        << FormatNumber(s.ci_high_mm, 3) << ',' << FormatNumber(s.loa_low_mm, 3) << ','
        << FormatNumber(s.loa_high_mm, 3) << ',' << FormatNumber(s.mae_mm, 3) << ','
        << FormatNumber(s.max_abs_mm, 3) << ',' << FormatNumber(s.median_abs_mm, 3) << ','
        << ToString(m.verdict) << '\n';
  }
  WriteFileAtomically(file, out.str());
}

void WriteLandmarkCsvs(const AccuracyReport& report, const fs::path& dir) {
  std::ostringstream summary;
  summary << "landmark,n,missing,median_mm,mean_mm,max_mm\n";
  for (const LandmarkSummary& l : report.summary.landmarks) {
    summary << Cell(l.name) << ',' << l.n << ',' << l.missing << ',' << FormatNumber(l.median_mm)
            << ',' << FormatNumber(l.mean_mm) << ',' << FormatNumber(l.max_mm) << '\n';
  }
  WriteFileAtomically(dir / "landmarks.csv", summary.str());
  std::ostringstream each;
  each << "subject,landmark,frame,error_mm,height_only,missing,truth_x_mm,truth_y_mm,truth_z_mm,"
          "measured_x_mm,measured_y_mm,measured_z_mm\n";
  for (const SubjectComparison& s : report.subjects) {
    for (const LandmarkError& e : s.landmarks) {
      each << Cell(s.subject) << ',' << Cell(e.name) << ',' << s.landmark_frame << ','
           << FormatNumber(e.error_mm) << ',' << (e.height_only ? 1 : 0) << ','
           << (e.missing ? 1 : 0);
      for (int k = 0; k < 3; ++k) each << ',' << FormatNumber(e.truth_mm[k]);
      for (int k = 0; k < 3; ++k) each << ',' << (e.missing ? "" : FormatNumber(e.measured_mm[k]));
      each << '\n';
    }
  }
  WriteFileAtomically(dir / "landmark_errors.csv", each.str());
}

// The A/T pair: one line per measurement.
void WritePostureCsv(const PostureComparison& posture, const fs::path& file) {
  std::ostringstream out;
  out << "measurement,kind,measured_a_mm,measured_b_mm,difference_mm,truth_a_mm,truth_b_mm,judged,"
         "pass\n";
  for (const PostureRow& r : posture.rows) {
    out << Cell(r.name) << ',' << r.kind << ',' << FormatNumber(r.measured_a_mm) << ','
        << FormatNumber(r.measured_b_mm) << ',' << FormatNumber(r.difference_mm) << ','
        << FormatNumber(r.truth_a_mm) << ',' << FormatNumber(r.truth_b_mm) << ','
        << (r.judged ? 1 : 0) << ',' << (r.judged ? (r.pass ? "pass" : "fail") : "") << '\n';
  }
  WriteFileAtomically(file, out.str());
}

// The posture test: one line per pair that ran x measurement; `pass` is
// empty for a row shown only.
void WritePostureTestCsv(const std::vector<PostureComparison>& pairs, const fs::path& file) {
  std::ostringstream out;
  out << "subject,reference_posture,posture,measurement,kind,iso_class,reference_mm,posture_mm,"
         "difference_mm,limit_mm,pass,truth_reference_mm,truth_posture_mm\n";
  for (const PostureComparison& p : pairs) {
    for (const PostureRow& r : p.rows) {
      out << Cell(p.subject) << ',' << Cell(p.pose_a) << ',' << Cell(p.pose_b) << ','
          << Cell(r.name) << ',' << r.kind << ',' << r.iso_class << ','
          << FormatNumber(r.measured_a_mm) << ',' << FormatNumber(r.measured_b_mm) << ','
          << FormatNumber(r.difference_mm) << ',' << FormatNumber(r.limit_mm, 0) << ','
          << (r.judged ? (r.pass ? "pass" : "fail") : "") << ',' << FormatNumber(r.truth_a_mm)
          << ',' << FormatNumber(r.truth_b_mm) << '\n';
    }
  }
  WriteFileAtomically(file, out.str());
}

void WriteRepeatabilityCsv(const std::vector<RepeatabilityRow>& rows, const fs::path& file) {
  std::ostringstream out;
  out << "measurement,subjects,scans,within_subject_sd_mm,repeatability_coefficient_mm\n";
  for (const RepeatabilityRow& r : rows) {
    out << Cell(r.name) << ',' << r.stats.subjects << ',' << r.stats.values << ','
        << FormatNumber(r.stats.within_sd_mm, 3) << ',' << FormatNumber(r.stats.coefficient_mm, 3)
        << '\n';
  }
  WriteFileAtomically(file, out.str());
}

void WriteNotComparedCsv(const std::vector<NotCompared>& rows, const fs::path& file) {
  std::ostringstream out;
  out << "subject,measurement,where,reason\n";
  for (const NotCompared& r : rows) {
    out << Cell(r.subject) << ',' << Cell(r.measurement) << ',' << Cell(r.where) << ','
        << Cell(r.reason) << '\n';
  }
  WriteFileAtomically(file, out.str());
}

json ExtrasJson(const AccuracyReport& report) {
  json repeatability = json::array(), not_compared = json::array(), mapped = json::array();
  for (const RepeatabilityRow& r : report.repeatability) {
    repeatability.push_back(
        {{"measurement", r.name},
         {"subjects", r.stats.subjects},
         {"scans", r.stats.values},
         {"within_subject_sd_mm", NumberOrNull(r.stats.within_sd_mm)},
         {"repeatability_coefficient_mm", NumberOrNull(r.stats.coefficient_mm)}});
  }
  for (const NotCompared& r : report.not_compared) {
    not_compared.push_back({{"subject", r.subject},
                            {"measurement", r.measurement},
                            {"where", r.where},
                            {"reason", r.reason}});
  }
  for (const MappedName& m : report.mapped_names) {
    mapped.push_back({{"their_name", m.their_name},
                      {"measurement", m.measurement},
                      {"note", m.note},
                      {"rows", m.rows}});
  }
  return {
      {"repeatability", repeatability}, {"not_compared", not_compared}, {"mapped_names", mapped}};
}

json PostureTestJson(const std::vector<PostureComparison>& pairs) {
  const PostureSetSummary s = SummarizePostures(pairs);
  json postures = json::array(), measurements = json::array(), failed = json::array();
  for (const PostureSetRow& r : s.postures) {
    postures.push_back({{"posture", r.posture},
                        {"pairs", r.pairs},
                        {"held", r.held},
                        {"did_not_run", r.did_not_run},
                        {"lengths", {{"judged", r.lengths_judged}, {"passed", r.lengths_passed}}},
                        {"girths", {{"judged", r.girths_judged}, {"passed", r.girths_passed}}},
                        {"worst_subject", r.worst_subject},
                        {"worst_measurement", r.worst_measurement},
                        {"worst_difference_mm", NumberOrNull(r.worst_difference_mm)},
                        {"worst_limit_mm", NumberOrNull(r.worst_limit_mm)}});
  }
  for (const PostureMeasurementRow& m : s.measurements) {
    measurements.push_back(
        {{"measurement", m.name},
         {"kind", m.kind},
         {"limit_mm", NumberOrNull(m.limit_mm)},
         {"pairs", m.pairs},
         {"judged", m.judged},
         {"within", m.within},
         {"missing", m.missing},
         {"max_abs_difference_mm", NumberOrNull(m.max_abs_difference_mm)},
         {"max_abs_truth_difference_mm", NumberOrNull(m.max_abs_truth_difference_mm)},
         {"truth_beyond_limit", m.truth_beyond}});
  }
  for (const PostureComparison& p : pairs) {
    if (!p.error.empty())
      failed.push_back({{"subject", p.subject}, {"posture", p.pose_b}, {"error", p.error}});
  }
  return {{"headline", s.Headline()},
          {"reference_posture", s.reference},
          {"pairs", s.pairs},
          {"pairs_held", s.held},
          {"values_judged", s.values_judged},
          {"values_passed", s.values_passed},
          {"postures", postures},
          {"measurements", measurements},
          {"failed_pairs", failed}};
}

json ReportJson(const AccuracyReport& report) {
  const AccuracySummary& s = report.summary;
  json verdicts = json::object();
  for (const MeasurementSummary& m : s.measurements) verdicts[m.name] = ToString(m.verdict);
  json failures = json::array();
  for (const SubjectFailure& f : report.failures) {
    failures.push_back({{"subject", f.subject}, {"stage", f.stage}, {"error", f.error}});
  }
  json out = {
      {"format", "bespoke-accuracy-report"},
      {"version", 1},
      {"created_utc", report.created_utc},
      {"reference", report.reference_label},
      {"settings", report.settings},
      {"subjects_compared", s.subjects},
      {"subjects_failed", report.failures.size()},
      {"failures", failures},
      {"iso_20685_1", {{"passed", s.passed}, {"failed", s.failed}, {"not_judged", s.not_judged}}},
      {"large_girth_mae_mm", NumberOrNull(s.large_girth_mae_mm)},
      {"median_landmark_error_mm", NumberOrNull(s.median_landmark_error_mm)},
      {"landmark_frame", s.landmark_frame},
      {"verdicts", verdicts}};
  out.update(ExtrasJson(report));
  if (report.posture) {
    const PostureComparison& p = *report.posture;
    out["posture"] = {{"pose_a", p.pose_a},
                      {"pose_b", p.pose_b},
                      {"arm_a_deg", p.arm_a_deg},
                      {"arm_b_deg", p.arm_b_deg},
                      {"tolerance_mm", p.tolerance_mm},
                      {"judged", p.judged},
                      {"passed", p.passed},
                      {"max_abs_difference_mm", NumberOrNull(p.max_abs_difference_mm)},
                      {"pass", p.pass()},
                      {"error", p.error}};
  }
  if (!report.posture_pairs.empty()) out["posture_test"] = PostureTestJson(report.posture_pairs);
  return out;
}

}  // namespace

std::string FormatNumber(double value, int digits) {
  if (!std::isfinite(value)) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, value);
  return buffer;
}

void WriteAccuracyReport(const AccuracyReport& report, const fs::path& dir) {
  CreateDirectories(dir);
  WriteMeasurementsCsv(report, dir / "measurements.csv");
  WriteSummaryCsv(report, dir / "summary.csv");
  if (!report.summary.landmarks.empty()) WriteLandmarkCsvs(report, dir);
  // One posture.csv: the posture test's, else the A/T pair's (the run
  // options never make both).
  if (!report.posture_pairs.empty()) {
    WritePostureTestCsv(report.posture_pairs, dir / "posture.csv");
  } else if (report.posture) {
    WritePostureCsv(*report.posture, dir / "posture.csv");
  }
  if (!report.repeatability.empty())
    WriteRepeatabilityCsv(report.repeatability, dir / "repeatability.csv");
  if (!report.not_compared.empty())
    WriteNotComparedCsv(report.not_compared, dir / "not_compared.csv");
  WriteJsonFile(dir / "settings.json", report.settings);
  WriteJsonFile(dir / "report.json", ReportJson(report));
  const std::vector<std::string> plots = WriteAccuracyPlots(report, dir);
  WriteFileAtomically(dir / "index.html", AccuracyHtml(report, plots));
}

}  // namespace bespoke
