// Printable SVG of a pattern at 1:1 in millimetres (width/height in mm, the
// viewBox in mm, so printing at 100 % gives true size).
//
// Pieces are laid out left to right in rows (y flipped: the pattern's y is
// up, SVG's is down), each with its sew line (solid), the cut line with seam
// allowance (dashed, when seam_allowance_mm > 0), the grain line with an
// arrow head, notches as 6 mm ticks into the allowance, internal lines, and a
// label (piece name, "cut N", mirrored / on fold) at the piece's centre.
// A 100 mm test square in the corner checks the print scale.
#ifndef BESPOKE_RESIZE_IO_PATTERN_SVG_H_
#define BESPOKE_RESIZE_IO_PATTERN_SVG_H_

#include <filesystem>
#include <string>

#include "resize/pattern/pattern.h"

namespace bespoke {

struct SvgOptions {
  double seam_allowance_mm = 10;  // cut line offset; 0 draws no cut line. Default 10 mm.
  double gap_mm = 30;             // space between pieces. Default 30 mm.
  double row_width_mm = 1500;     // start a new row past this width. Default 1500 mm.
  void Check() const;             // InputError for negative values
};

std::string PatternToSvg(const SvgOptions& options, const Pattern& pattern);
void WritePatternSvg(const SvgOptions& options, const Pattern& pattern,
                     const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_PATTERN_SVG_H_
