// Import of GarmentCode / NVIDIA sewing-pattern JSON (the "pattern" section:
// panels with 2-D vertices and directed edges, straight or curved, and
// "stitches" pairing panel edges). Comments (//) are allowed, as in the
// specification template.
//
// Units: "properties.units_in_meter" units make one metre (default 100, cm);
// coordinates are converted to mm. Curves: quadratic and cubic Beziers with
// control points relative to the edge (x along it, y along it rotated +90
// degrees; "curvature_coords": "absolute" also accepted) and circular arcs
// ("circle": radius, large-arc flag, right flag: the small arc bulges to the
// right of the edge direction when the flag is 1). Every edge is sampled to
// the same number of points (`samples_per_edge`, its end belonging to the
// next edge), so any two stitched edges have equal point counts; a stitch
// becomes a seam pairing both edges start-to-start (GarmentCode stitches
// connect edge starts, as in its specification template). Panels become
// pieces (counter-clockwise; cut 1; 3-D placement ignored). No landmarks or
// bindings exist in the format: add them with a sidecar (ApplySidecar).
// Malformed input throws InputError naming the file, panel and edge.
#ifndef BESPOKE_RESIZE_IO_GARMENTCODE_H_
#define BESPOKE_RESIZE_IO_GARMENTCODE_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "resize/pattern/pattern.h"

namespace bespoke {

struct GarmentCodeOptions {
  int samples_per_edge = 10;  // points per edge (>= 1); default 10
  void Check() const;
};

Pattern PatternFromGarmentCode(const GarmentCodeOptions& options, const nlohmann::json& document,
                               const std::string& what);
Pattern ReadGarmentCode(const GarmentCodeOptions& options, const std::filesystem::path& file);

// True when `document` looks like GarmentCode (has "pattern" with "panels").
bool IsGarmentCode(const nlohmann::json& document);

// Parses JSON text allowing // and /* */ comments; InputError naming `what`.
nlohmann::json ParseJsonWithComments(const std::string& text, const std::string& what);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_GARMENTCODE_H_
