// Bespoke's own pattern format: JSON, millimetres, documented in
// docs/pattern-format.md ("format": "bespoke-pattern", "version": 1).
//
// Reading validates the structure (ValidatePattern) and throws InputError
// naming the file and the offending piece/seam/binding. Writing is atomic.
//
// The same parser reads the pieces-less "sidecar" that adds landmarks,
// critical points, seams and bindings to pieces imported from DXF
// (ApplySidecar); a sidecar may place a landmark by "near": [x, y] (snapped to
// the nearest outline vertex) and give seam ends as landmark names.
#ifndef BESPOKE_RESIZE_IO_PATTERN_JSON_H_
#define BESPOKE_RESIZE_IO_PATTERN_JSON_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "resize/pattern/pattern.h"

namespace bespoke {

nlohmann::json PatternToJson(const Pattern& pattern);
// `what` names the source in error messages. Validates.
Pattern PatternFromJson(const nlohmann::json& document, const std::string& what);

Pattern ReadPatternJson(const std::filesystem::path& file);
void WritePatternJson(const Pattern& pattern, const std::filesystem::path& file);

// Adds the sidecar's "pieces" entries (matched by name: landmarks, critical,
// notches, grain, cut_count ...), "seams" and "bindings" to `pattern`, then
// validates. Throws InputError naming `what` for unknown pieces.
void ApplySidecar(const nlohmann::json& sidecar, const std::string& what, Pattern* pattern);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_PATTERN_JSON_H_
