// MakeHuman morph targets (.target files, CC0 assets from
// ../shared/data/bodies/makehuman/targets): sparse per-vertex offsets of the
// base mesh. A body is base + sum_i weight_i * target_i.
//
// File format: one `vertex_index dx dy dz` per line (index into base.obj's
// vertex list, 0-based; offsets in the base mesh's units, decimetres, and
// axes, y up); '#' starts a comment; blank lines are ignored.
// Failure: InputError("<file>: line N: <what>") for a line that is not four
// numbers, a negative or non-integer index, a non-finite offset, a repeated
// index; InputError naming the file when it cannot be read.
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_TARGET_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_TARGET_H_

#include <filesystem>
#include <string_view>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

struct MakeHumanTarget {
  std::vector<int> vertex;  // #T base.obj vertex indices (distinct)
  Eigen::MatrixX3d offset;  // #T x 3 offsets, decimetres, MakeHuman axes
};

// Parses the text of a target file; `file` names it in errors.
MakeHumanTarget ParseMakeHumanTarget(std::string_view text, const std::filesystem::path& file);

// Reads and parses a target file.
MakeHumanTarget ReadMakeHumanTarget(const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_TARGET_H_
