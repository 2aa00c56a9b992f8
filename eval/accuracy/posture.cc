#include "eval/accuracy/posture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

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

}  // namespace

PostureComparison ComparePostures(const json& measured_a, const json& measured_b,
                                  const json& truth_a, const json& truth_b, double tolerance_mm) {
  if (!(tolerance_mm > 0)) throw InputError("posture tolerance must be positive");
  if (measured_a.is_null() || measured_b.is_null())
    throw InputError("posture: both poses need measurements");
  PostureComparison result;
  result.tolerance_mm = tolerance_mm;
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
    row.judged = row.kind == "length";
    if (row.judged) {
      ++result.judged;
      row.pass = std::isfinite(row.difference_mm) && std::abs(row.difference_mm) <= tolerance_mm;
      if (row.pass) ++result.passed;
      if (std::isfinite(row.difference_mm) &&
          !(std::abs(row.difference_mm) <= result.max_abs_difference_mm)) {
        result.max_abs_difference_mm = std::abs(row.difference_mm);
      }
    }
    result.rows.push_back(row);
  }
  return result;
}

}  // namespace bespoke
