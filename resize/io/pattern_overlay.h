// An overlay picture of several versions of one pattern (the base, the
// graded start, the fit, another system's draft), piece by piece, for a
// tailor's eye check: a distorted piece, a kinked edge or a tilted line shows
// at once.
//
// Every layer draws the pieces it shares (by name) with the first layer, in
// the piece's own frame (mm, x right, y up) unless the layer gives a rigid
// placement for it. Each piece gets one cell holding all its layers; cells
// are laid out left to right in rows, scaled to `px_per_mm`, with the piece
// name, a legend of the layers and a 100 mm scale bar. Cairo draws inside
// pattern_overlay.cc; the file is written atomically.
#ifndef BESPOKE_RESIZE_IO_PATTERN_OVERLAY_H_
#define BESPOKE_RESIZE_IO_PATTERN_OVERLAY_H_

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

struct OverlayLayer {
  std::string label;                        // legend text, e.g. "fitted"
  const Pattern* pattern = nullptr;         // pieces matched to the first layer's by name
  std::array<double, 3> color = {0, 0, 0};  // RGB 0-1
  double line_px = 1.5;                     // line width in pixels
  bool dashed = false;
  // Optional per piece name: a 2 x 3 rigid placement [R | t] applied to that
  // piece's points (mm), e.g. another system's draft aligned onto the fit.
  std::map<std::string, Eigen::Matrix<double, 2, 3>> placement;
};

struct OverlayOptions {
  double px_per_mm = 0.5;           // picture scale. Default 0.5 px per mm.
  double gap_mm = 40;               // space between cells. Default 40 mm.
  double row_width_mm = 2400;       // start a new row past this width. Default 2400 mm.
  std::vector<std::string> pieces;  // only these pieces, in this order; empty = all
  bool landmarks = true;            // mark outline landmarks of the first layer. Default on.
  void Check() const;               // InputError for non-positive scale or negative gaps
};

// Writes the overlay of `layers` (at least one, each with a pattern) to
// `file` (.png). InputError for an empty layer list, a missing pattern, a
// picture larger than 16000 px a side, or another extension.
void WritePatternOverlay(const OverlayOptions& options, const std::vector<OverlayLayer>& layers,
                         const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_PATTERN_OVERLAY_H_
