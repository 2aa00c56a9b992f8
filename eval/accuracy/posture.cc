#include "eval/accuracy/posture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "eval/accuracy/iso_20685.h"
#include "measure/catalogue/catalogue.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using nlohmann::json;

struct Value {
  double value_mm = kNaN;
  std::string kind;
};

// name -> value, in document order (names listed in `order`).
std::map<std::string, Value> Values(const json& document, const std::string& what,
                                    std::vector<std::string>* order) {
  std::map<std::string, Value> values;
  if (document.is_null()) return values;
  if (!document.is_object() || !document.contains("measurements") ||
      !document["measurements"].is_array()) {
    throw InputError(what + ": no \"measurements\" array");
  }
  for (const json& m : document["measurements"]) {
    if (!m.is_object() || !m.contains("name") || !m["name"].is_string()) continue;
    Value v;
    v.kind = m.value("kind", std::string());
    if (m.contains("value_mm") && m["value_mm"].is_number())
      v.value_mm = m["value_mm"].get<double>();
    const std::string name = m["name"].get<std::string>();
    if (order && std::find(order->begin(), order->end(), name) == order->end())
      order->push_back(name);
    values[name] = v;
  }
  return values;
}

double Get(const std::map<std::string, Value>& values, const std::string& name) {
  const auto it = values.find(name);
  return it == values.end() ? kNaN : it->second.value_mm;
}

// The |B - A| allowed for measurement `name` of `kind` under `rule`; NaN
// when the rule does not judge it. Sets `iso_class` ("" when the catalogue
// lacks the name).
double LimitOf(PostureRule rule, const std::string& name, const std::string& kind,
               double tolerance_mm, std::string* iso_class) {
  const Catalogue& catalogue = Catalogue::Builtin();
  const bool known = catalogue.HasMeasurement(name);
  const IsoClass c = known ? IsoClassOf(catalogue.Measurement(name)) : IsoClass::kHeight;
  *iso_class = known ? ToString(c) : std::string();
  if (rule == PostureRule::kLengths) return kind == "length" ? tolerance_mm : kNaN;
  if (!known) return kNaN;
  if (c == IsoClass::kSegmentLength) return tolerance_mm;
  if (c == IsoClass::kSmallGirth || c == IsoClass::kLargeGirth) return IsoToleranceMm(c);
  return kNaN;  // heights and breadths: shown only
}

// How far a judged row is over its limit: |difference| / limit; a missing
// value is the worst (infinity).
double Excess(double difference_mm, double limit_mm) {
  return std::isfinite(difference_mm) ? std::abs(difference_mm) / limit_mm
                                      : std::numeric_limits<double>::infinity();
}

// Adds a judged `row` (index `i`) to the counters of `result`.
void Count(const PostureRow& row, int i, PostureComparison* result) {
  const bool length = row.kind == "length", girth = row.kind == "girth";
  ++result->judged;
  result->lengths_judged += length;
  result->girths_judged += girth;
  if (row.pass) {
    ++result->passed;
    result->lengths_passed += length;
    result->girths_passed += girth;
  }
  if (std::isfinite(row.difference_mm) &&
      !(std::abs(row.difference_mm) <= result->max_abs_difference_mm)) {
    result->max_abs_difference_mm = std::abs(row.difference_mm);
  }
  const PostureRow* worst = result->worst >= 0 ? &result->rows[result->worst] : nullptr;
  if (!worst ||
      Excess(row.difference_mm, row.limit_mm) > Excess(worst->difference_mm, worst->limit_mm)) {
    result->worst = i;
  }
}

}  // namespace

PostureComparison ComparePostures(const json& measured_a, const json& measured_b,
                                  const json& truth_a, const json& truth_b, double tolerance_mm,
                                  PostureRule rule) {
  if (!(tolerance_mm > 0)) throw InputError("posture tolerance must be positive");
  if (measured_a.is_null() || measured_b.is_null())
    throw InputError("posture: both poses need measurements");
  PostureComparison result;
  result.tolerance_mm = tolerance_mm;
  result.rule = rule;
  // Rows: the truth's measurements (a measured pose lacking one is a failed
  // length, not a silent gap), then any other measured ones.
  std::vector<std::string> order;
  const auto ta = Values(truth_a, "pose A truth", &order);
  const auto tb = Values(truth_b, "pose B truth", nullptr);
  const auto a = Values(measured_a, "pose A measurements", &order);
  const auto b = Values(measured_b, "pose B measurements", &order);
  result.max_abs_difference_mm = kNaN;
  for (const std::string& name : order) {
    PostureRow row;
    row.name = name;
    for (const auto* values : {&ta, &a, &b}) {
      if (row.kind.empty() && values->count(name)) row.kind = values->at(name).kind;
    }
    row.measured_a_mm = Get(a, name);
    row.measured_b_mm = Get(b, name);
    row.truth_a_mm = Get(ta, name);
    row.truth_b_mm = Get(tb, name);
    row.difference_mm = row.measured_b_mm - row.measured_a_mm;  // NaN propagates
    row.limit_mm = LimitOf(rule, name, row.kind, tolerance_mm, &row.iso_class);
    row.judged = std::isfinite(row.limit_mm);
    row.pass = row.judged && std::isfinite(row.difference_mm) &&
               std::abs(row.difference_mm) <= row.limit_mm;
    result.rows.push_back(row);
    if (row.judged) Count(row, static_cast<int>(result.rows.size()) - 1, &result);
  }
  return result;
}

namespace {

// Adds the pair `p` (which ran) to its posture's row.
void AddToPosture(const PostureComparison& p, PostureSetRow* row) {
  row->held += p.pass();
  row->lengths_judged += p.lengths_judged;
  row->lengths_passed += p.lengths_passed;
  row->girths_judged += p.girths_judged;
  row->girths_passed += p.girths_passed;
  if (p.worst < 0) return;
  const PostureRow& w = p.rows[p.worst];
  if (row->worst_measurement.empty() ||
      Excess(w.difference_mm, w.limit_mm) > Excess(row->worst_difference_mm, row->worst_limit_mm)) {
    row->worst_subject = p.subject;
    row->worst_measurement = w.name;
    row->worst_difference_mm = w.difference_mm;
    row->worst_limit_mm = w.limit_mm;
  }
}

// Adds the rows of the pair `p` (which ran) to the per-measurement rows.
void AddToMeasurements(const PostureComparison& p, std::vector<PostureMeasurementRow>* rows,
                       std::map<std::string, std::size_t>* index) {
  for (const PostureRow& r : p.rows) {
    auto it = index->find(r.name);
    if (it == index->end()) {
      it = index->emplace(r.name, rows->size()).first;
      PostureMeasurementRow m;
      m.name = r.name;
      m.kind = r.kind;
      m.iso_class = r.iso_class;
      m.limit_mm = r.limit_mm;
      m.max_abs_difference_mm = m.max_abs_truth_difference_mm = kNaN;
      rows->push_back(m);
    }
    PostureMeasurementRow& m = (*rows)[it->second];
    ++m.pairs;
    m.judged += r.judged;
    m.within += r.pass;
    m.missing += !std::isfinite(r.difference_mm);
    if (std::isfinite(r.difference_mm) && !(std::abs(r.difference_mm) <= m.max_abs_difference_mm)) {
      m.max_abs_difference_mm = std::abs(r.difference_mm);
      m.max_subject = p.subject;
      m.max_posture = p.pose_b;
    }
    const double truth = std::abs(r.truth_b_mm - r.truth_a_mm);
    if (std::isfinite(truth) && !(truth <= m.max_abs_truth_difference_mm))
      m.max_abs_truth_difference_mm = truth;
    m.truth_beyond += r.judged && std::isfinite(truth) && truth > r.limit_mm;
  }
}

}  // namespace

PostureSetSummary SummarizePostures(const std::vector<PostureComparison>& pairs) {
  PostureSetSummary s;
  std::map<std::string, std::size_t> posture_index, measurement_index;
  for (const PostureComparison& p : pairs) {
    if (s.reference.empty()) s.reference = p.pose_a;
    auto it = posture_index.find(p.pose_b);
    if (it == posture_index.end()) {
      it = posture_index.emplace(p.pose_b, s.postures.size()).first;
      PostureSetRow row;
      row.posture = p.pose_b;
      s.postures.push_back(row);
    }
    PostureSetRow& row = s.postures[it->second];
    ++row.pairs;
    ++s.pairs;
    if (!p.error.empty()) {
      ++row.did_not_run;
      continue;
    }
    AddToPosture(p, &row);
    AddToMeasurements(p, &s.measurements, &measurement_index);
    s.held += p.pass();
    s.values_judged += p.judged;
    s.values_passed += p.passed;
  }
  return s;
}

std::string PostureSetSummary::Headline() const {
  return "posture: " + std::to_string(held) + " of " + std::to_string(pairs) +
         " subject x posture pairs hold; " + std::to_string(values_passed) + " of " +
         std::to_string(values_judged) + " values within limit";
}

}  // namespace bespoke
