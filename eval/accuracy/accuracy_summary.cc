#include "eval/accuracy/accuracy_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace bespoke {
namespace {

// Names in catalogue order first, then the others in order of appearance.
std::vector<std::string> Ordered(const std::vector<std::string>& catalogue_order,
                                 const std::vector<std::string>& seen) {
  std::vector<std::string> out;
  for (const std::string& name : catalogue_order) {
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) out.push_back(name);
  }
  for (const std::string& name : seen) {
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}

IsoClass ClassOf(const Catalogue& catalogue, const std::string& name, const std::string& kind) {
  if (catalogue.HasMeasurement(name)) return IsoClassOf(catalogue.Measurement(name));
  if (kind == "height") return IsoClass::kHeight;
  if (kind == "girth") return IsoClass::kSmallGirth;
  return IsoClass::kSegmentLength;
}

}  // namespace

AccuracySummary SummarizeAccuracy(const std::vector<SubjectComparison>& subjects,
                                  const Catalogue& catalogue) {
  AccuracySummary summary;
  summary.subjects = static_cast<int>(subjects.size());
  std::map<std::string, MeasurementSummary> by_name;
  std::vector<std::string> seen;
  std::map<std::string, std::vector<double>> landmark_errors;
  std::map<std::string, int> landmark_missing;
  std::vector<std::string> landmarks_seen;
  std::vector<double> all_landmark_errors;
  for (const SubjectComparison& subject : subjects) {
    if (summary.landmark_frame.empty()) summary.landmark_frame = subject.landmark_frame;
    if (summary.landmark_frame != subject.landmark_frame) summary.landmark_frame = "mixed";
    for (const MeasurementDifference& d : subject.measurements) {
      auto [it, inserted] = by_name.try_emplace(d.name);
      MeasurementSummary& m = it->second;
      if (inserted) {
        seen.push_back(d.name);
        m.name = d.name;
        m.kind = d.kind;
        m.iso_class = ClassOf(catalogue, d.name, d.kind);
        m.tolerance_mm = IsoToleranceMm(m.iso_class);
      }
      if (d.missing) {
        ++m.missing;
      } else {
        m.differences_mm.push_back(d.difference_mm);
        m.means_mm.push_back(0.5 * (d.measured_mm + d.truth_mm));
      }
      if (!d.flags.empty()) ++m.flagged;
      if (!d.truth_flags.empty()) ++m.truth_flagged;
    }
    for (const LandmarkError& e : subject.landmarks) {
      if (!landmark_errors.count(e.name) && !landmark_missing.count(e.name))
        landmarks_seen.push_back(e.name);
      if (e.missing) {
        ++landmark_missing[e.name];
        landmark_errors[e.name];
      } else {
        landmark_errors[e.name].push_back(e.error_mm);
        landmark_missing[e.name];
        all_landmark_errors.push_back(e.error_mm);
      }
    }
  }

  std::vector<std::string> catalogue_measurements, catalogue_landmarks;
  for (const MeasurementDef& m : catalogue.measurements()) catalogue_measurements.push_back(m.name);
  for (const LandmarkDef& l : catalogue.landmarks()) catalogue_landmarks.push_back(l.name);

  double large_sum = 0;
  int large_n = 0;
  for (const std::string& name : Ordered(catalogue_measurements, seen)) {
    MeasurementSummary m = by_name[name];
    m.stats = SummarizeErrors(m.differences_mm);
    m.verdict = JudgeIso20685(m.stats, m.tolerance_mm);
    if (m.verdict == IsoVerdict::kPass) ++summary.passed;
    if (m.verdict == IsoVerdict::kFail) ++summary.failed;
    if (m.verdict == IsoVerdict::kNotJudged) ++summary.not_judged;
    if (m.iso_class == IsoClass::kLargeGirth) {
      for (double d : m.differences_mm) large_sum += std::abs(d);
      large_n += static_cast<int>(m.differences_mm.size());
    }
    summary.measurements.push_back(std::move(m));
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  summary.large_girth_mae_mm = large_n ? large_sum / large_n : kNaN;
  summary.median_landmark_error_mm = Median(all_landmark_errors);

  for (const std::string& name : Ordered(catalogue_landmarks, landmarks_seen)) {
    LandmarkSummary l;
    l.name = name;
    const std::vector<double>& errors = landmark_errors[name];
    l.n = static_cast<int>(errors.size());
    l.missing = landmark_missing[name];
    l.median_mm = Median(errors);
    l.mean_mm = l.max_mm = kNaN;
    if (!errors.empty()) {
      double sum = 0;
      l.max_mm = 0;
      for (double e : errors) {
        sum += e;
        l.max_mm = std::max(l.max_mm, e);
      }
      l.mean_mm = sum / l.n;
    }
    summary.landmarks.push_back(l);
  }
  return summary;
}

}  // namespace bespoke
