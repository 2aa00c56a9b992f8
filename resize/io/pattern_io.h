// Loading a pattern from any supported file: Bespoke pattern JSON, GarmentCode
// JSON (told apart by content) or DXF-AAMA/ASTM (by the .dxf extension), with
// an optional sidecar JSON adding landmarks, seams and bindings (needed for
// DXF and GarmentCode, whose formats have none). Throws InputError naming the
// file for anything unreadable or invalid.
#ifndef BESPOKE_RESIZE_IO_PATTERN_IO_H_
#define BESPOKE_RESIZE_IO_PATTERN_IO_H_

#include <filesystem>

#include "resize/pattern/pattern.h"

namespace bespoke {

// `sidecar` may be empty (none).
Pattern LoadPattern(const std::filesystem::path& file, const std::filesystem::path& sidecar);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_PATTERN_IO_H_
