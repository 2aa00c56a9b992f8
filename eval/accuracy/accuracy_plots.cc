// The report's charts (scanners/render/plot.h). Measurements and landmarks
// are numbered along the x axis in table order; index.html gives the names.
#include <algorithm>
#include <cmath>
#include <limits>

#include "eval/accuracy/accuracy_report.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/constants.h"
#include "scanners/render/plot.h"

namespace bespoke {
namespace fs = std::filesystem;

namespace {

constexpr std::array<double, 3> kSubjects = {0.55, 0.65, 0.8}, kBias = {0.8, 0.1, 0.1},
                                kCi = {0.1, 0.2, 0.7}, kLimit = {0.2, 0.6, 0.2};

// A dashed horizontal line at `y` over [x0, x1].
Series HorizontalLine(double y, double x0, double x1, const std::string& label) {
  Series s;
  s.label = label;
  s.x = {x0, x1};
  s.y = {y, y};
  s.dashed = true;
  s.color = kLimit;
  return s;
}

// Every subject's difference (points), the bias (points) and its 95 % CI
// (vertical segments) per measurement of one ISO class, with the limits.
void StripChart(const std::vector<const MeasurementSummary*>& measurements, IsoClass iso_class,
                const std::string& reference_label, const fs::path& file) {
  Chart chart;
  chart.title =
      "Error distribution: " + ToString(iso_class) + " (measured - " + reference_label + ")";
  chart.x_label = "measurement (number as in the table)";
  chart.y_label = "error (mm)";
  Series subjects{"subjects", {}, {}, Series::Style::kPoints, kSubjects};
  Series bias{"bias (mean)", {}, {}, Series::Style::kPoints, kBias};
  Series ci{"95 % CI of the mean", {}, {}, Series::Style::kLine, kCi};
  double tolerance = 0;
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    const MeasurementSummary& m = *measurements[i];
    const double x = static_cast<double>(i + 1);
    const std::size_t n = m.differences_mm.size();
    for (std::size_t j = 0; j < n; ++j) {
      // Spread the subjects a little sideways so equal values stay visible.
      const double dx =
          n > 1 ? 0.3 * (static_cast<double>(j) / static_cast<double>(n - 1) - 0.5) : 0.0;
      subjects.x.push_back(x + dx);
      subjects.y.push_back(m.differences_mm[j]);
    }
    bias.x.push_back(x);
    bias.y.push_back(m.stats.mean_mm);
    ci.x.insert(ci.x.end(), {x, x, x});
    ci.y.insert(ci.y.end(), {m.stats.ci_low_mm, m.stats.ci_high_mm, kNaN});
    tolerance = m.tolerance_mm;
  }
  const double x1 = static_cast<double>(measurements.size()) + 0.5;
  chart.series = {subjects, ci, bias,
                  HorizontalLine(tolerance, 0.5, x1,
                                 "ISO 20685-1 limit +/-" + FormatNumber(tolerance, 0) + " mm"),
                  HorizontalLine(-tolerance, 0.5, x1, "")};
  // The y range fits the subjects and the limits; a wider CI (few subjects)
  // runs off the chart (its numbers are in the table).
  double lo = -tolerance, hi = tolerance;
  for (double y : subjects.y) lo = std::min(lo, y), hi = std::max(hi, y);
  // Room at the top for the legend (drawn top right, over the data otherwise).
  const double pad = 0.08 * (hi - lo);
  chart.y_min = lo - pad;
  chart.y_max = hi + 0.35 * (hi - lo);
  chart.x_min = 0.5;
  chart.x_max = x1;
  chart.width_px = std::max(600, 60 * static_cast<int>(measurements.size()) + 200);
  WriteChart(chart, file);
}

void HistogramChart(const MeasurementSummary& m, const std::string& reference_label,
                    const fs::path& file) {
  Chart chart;
  chart.title = m.name + " (" + ToString(m.iso_class) + ")";
  chart.x_label = "measured - " + reference_label + " (mm)";
  chart.y_label = "subjects";
  chart.width_px = 480;
  chart.height_px = 300;
  const int bins = std::clamp(static_cast<int>(m.differences_mm.size()) / 3, 5, 20);
  double lo = -m.tolerance_mm, hi = m.tolerance_mm;
  for (double d : m.differences_mm) lo = std::min(lo, d), hi = std::max(hi, d);
  chart.series.push_back(HistogramSeries(m.differences_mm, bins, "", lo, hi));
  double top = 1;
  for (double count : chart.series.back().y) top = std::max(top, count);
  chart.series.push_back({"ISO 20685-1 limit",
                          {-m.tolerance_mm, -m.tolerance_mm},
                          {0, top},
                          Series::Style::kLine,
                          kLimit});
  chart.series.back().dashed = true;
  chart.series.push_back(
      {"", {m.tolerance_mm, m.tolerance_mm}, {0, top}, Series::Style::kLine, kLimit});
  chart.series.back().dashed = true;
  WriteChart(chart, file);
}

// Bland-Altman plot: each subject's difference against the mean of its
// measured and reference values, with the bias, the 95 % limits of agreement
// and the ISO 20685-1 limit.
void BlandAltmanChart(const MeasurementSummary& m, const std::string& reference_label,
                      const fs::path& file) {
  Chart chart;
  chart.title = m.name + ": Bland-Altman";
  chart.x_label = "mean of measured and " + reference_label + " (mm)";
  chart.y_label = "measured - " + reference_label + " (mm)";
  chart.width_px = 560;
  chart.height_px = 380;
  double x0 = m.means_mm.front(), x1 = x0;
  for (double x : m.means_mm) x0 = std::min(x0, x), x1 = std::max(x1, x);
  const double pad = std::max(1.0, 0.05 * (x1 - x0));
  x0 -= pad;
  x1 += pad;
  Series subjects{"subjects", m.means_mm, m.differences_mm, Series::Style::kPoints, kSubjects};
  Series bias =
      HorizontalLine(m.stats.mean_mm, x0, x1, "bias " + FormatNumber(m.stats.mean_mm, 1) + " mm");
  bias.dashed = false;
  bias.color = kBias;
  chart.series = {subjects, bias};
  if (std::isfinite(m.stats.loa_low_mm)) {
    Series low =
        HorizontalLine(m.stats.loa_low_mm, x0, x1, "limits of agreement (bias +/- 1.96 SD)");
    low.color = kCi;
    Series high = HorizontalLine(m.stats.loa_high_mm, x0, x1, "");
    high.color = kCi;
    chart.series.insert(chart.series.end(), {low, high});
  }
  chart.series.push_back(HorizontalLine(
      m.tolerance_mm, x0, x1, "ISO 20685-1 limit +/-" + FormatNumber(m.tolerance_mm, 0) + " mm"));
  chart.series.push_back(HorizontalLine(-m.tolerance_mm, x0, x1, ""));
  double lo = -m.tolerance_mm, hi = m.tolerance_mm;
  for (double y : m.differences_mm) lo = std::min(lo, y), hi = std::max(hi, y);
  for (double y : {m.stats.loa_low_mm, m.stats.loa_high_mm}) {
    if (std::isfinite(y)) lo = std::min(lo, y), hi = std::max(hi, y);
  }
  // Room at the top for the legend.
  chart.y_min = lo - 0.08 * (hi - lo);
  chart.y_max = hi + 0.45 * (hi - lo);
  chart.x_min = x0;
  chart.x_max = x1;
  WriteChart(chart, file);
}

void LandmarkChart(const std::vector<LandmarkSummary>& landmarks, const fs::path& file) {
  Chart chart;
  chart.title = "Landmark errors (3-D distance to the true datum point; levels: height)";
  chart.x_label = "landmark (number as in the table)";
  chart.y_label = "error (mm)";
  Series median{"median", {}, {}, Series::Style::kBars, kCi};
  Series mean{"mean", {}, {}, Series::Style::kPoints, kBias};
  Series max{"max", {}, {}, Series::Style::kPoints, kSubjects};
  for (std::size_t i = 0; i < landmarks.size(); ++i) {
    const double x = static_cast<double>(i + 1);
    median.x.push_back(x);
    median.y.push_back(landmarks[i].median_mm);
    mean.x.push_back(x);
    mean.y.push_back(landmarks[i].mean_mm);
    max.x.push_back(x);
    max.y.push_back(landmarks[i].max_mm);
  }
  median.bar_width = 0.7;
  chart.series = {median, mean, max};
  chart.x_min = 0.5;
  chart.x_max = static_cast<double>(landmarks.size()) + 0.5;
  chart.width_px = std::max(700, 28 * static_cast<int>(landmarks.size()) + 200);
  WriteChart(chart, file);
}

void PostureChart(const PostureComparison& posture, const fs::path& file) {
  Chart chart;
  chart.title = "Posture: " + posture.pose_b + " - " + posture.pose_a + " per length";
  chart.x_label = "length (number as in the posture table)";
  chart.y_label = "difference (mm)";
  Series measured{"measured", {}, {}, Series::Style::kBars, kCi};
  Series truth{"truth (body itself)", {}, {}, Series::Style::kPoints, kBias};
  int k = 0;
  for (const PostureRow& row : posture.rows) {
    if (!row.judged) continue;
    const double x = ++k;
    measured.x.push_back(x);
    measured.y.push_back(row.difference_mm);
    truth.x.push_back(x);
    truth.y.push_back(row.truth_b_mm - row.truth_a_mm);
  }
  measured.bar_width = 0.7;
  const double x1 = k + 0.5;
  chart.series = {measured, truth,
                  HorizontalLine(posture.tolerance_mm, 0.5, x1,
                                 "+/-" + FormatNumber(posture.tolerance_mm, 0) + " mm"),
                  HorizontalLine(-posture.tolerance_mm, 0.5, x1, "")};
  chart.x_min = 0.5;
  chart.x_max = x1;
  WriteChart(chart, file);
}

}  // namespace

std::vector<std::string> WriteAccuracyPlots(const AccuracyReport& report, const fs::path& dir) {
  CreateDirectories(dir / "plots");
  std::vector<std::string> written;
  for (IsoClass c : {IsoClass::kLargeGirth, IsoClass::kSmallGirth, IsoClass::kSegmentLength,
                     IsoClass::kBreadth, IsoClass::kHeight}) {
    std::vector<const MeasurementSummary*> chosen;
    for (const MeasurementSummary& m : report.summary.measurements) {
      if (m.iso_class == c && !m.differences_mm.empty()) chosen.push_back(&m);
    }
    if (chosen.empty()) continue;
    const std::string name = "plots/errors_" + ToString(c) + ".png";
    StripChart(chosen, c, report.reference_label, dir / name);
    written.push_back(name);
  }
  for (const MeasurementSummary& m : report.summary.measurements) {
    if (m.differences_mm.empty()) continue;
    const std::string name = "plots/hist_" + m.name + ".png";
    HistogramChart(m, report.reference_label, dir / name);
    written.push_back(name);
    const std::string bland_altman = "plots/bland_altman_" + m.name + ".png";
    BlandAltmanChart(m, report.reference_label, dir / bland_altman);
    written.push_back(bland_altman);
  }
  const bool any_landmark =
      std::any_of(report.summary.landmarks.begin(), report.summary.landmarks.end(),
                  [](const LandmarkSummary& l) { return l.n > 0; });
  if (any_landmark) {
    LandmarkChart(report.summary.landmarks, dir / "plots/landmarks.png");
    written.push_back("plots/landmarks.png");
  }
  if (report.posture && report.posture->judged > 0) {
    PostureChart(*report.posture, dir / "plots/posture.png");
    written.push_back("plots/posture.png");
  }
  return written;
}

}  // namespace bespoke
