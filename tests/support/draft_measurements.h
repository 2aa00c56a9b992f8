// For process-level tests of `bespoke resize`: the measurement document
// (docs/contracts.md, mm) of the body a `bespoke draft` was made for, every
// measurement its bindings name taken once from draft.json's `body_mm` and
// multiplied by `scale` (1.08 = a body 8 % larger in every bound measurement).
// Throws nlohmann::json errors when draft.json is missing or malformed.
#ifndef BESPOKE_TESTS_SUPPORT_DRAFT_MEASUREMENTS_H_
#define BESPOKE_TESTS_SUPPORT_DRAFT_MEASUREMENTS_H_

#include <filesystem>
#include <nlohmann/json.hpp>

namespace bespoke::testing {

nlohmann::json ScaledDraftMeasurements(const std::filesystem::path& draft_json, double scale);

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_DRAFT_MEASUREMENTS_H_
