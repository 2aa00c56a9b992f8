#include "tests/support/draft_measurements.h"

#include <set>
#include <string>

#include "tests/support/run_command.h"

namespace bespoke::testing {

nlohmann::json ScaledDraftMeasurements(const std::filesystem::path& draft_json, double scale) {
  const nlohmann::json draft = nlohmann::json::parse(ReadText(draft_json));
  nlohmann::json measurements = nlohmann::json::array();
  std::set<std::string> seen;
  for (const auto& b : draft.at("bindings")) {
    const std::string name = b.at("measurement");
    if (!seen.insert(name).second) continue;
    measurements.push_back(
        {{"name", name}, {"value_mm", scale * b.at("body_mm").get<double>()}, {"flags", {}}});
  }
  return {{"format", "bespoke-measurements"},
          {"version", 1},
          {"units", "mm"},
          {"measurements", measurements}};
}

}  // namespace bespoke::testing
