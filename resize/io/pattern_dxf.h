// DXF-AAMA / DXF-ASTM (ASTM D6673) pattern files: the exchange format of
// garment CAD systems (Valentina, Gerber, Lectra, Optitex).
//
// Structure (as Valentina 0.7 writes it, and as we write it): one BLOCK per
// piece, inserted once in ENTITIES; layers by number:
//   1 cut line (closed polyline; with seam allowance) and piece text
//   14 sew line (ASTM) - or 8 (AAMA, where 8 also holds internal lines)
//   8 internal lines, 4 notches (ASTM: POINT with angle 50 and length 30;
//   AAMA: a short LINE), 7 grain line (LINE).
// Units: millimetres (Valentina writes mm; $INSUNITS, when present, is
// honoured: 1 inch, 4 mm, 5 cm, 6 m).
//
// Reading accepts R12 (POLYLINE/VERTEX/SEQEND) and 2000 (LWPOLYLINE) files,
// with INSERT translation/scale/rotation. A piece's outline is its sew line
// (14, else the largest closed polyline on 8, else the cut line on 1),
// turned counter-clockwise (with a note, edit.h), repeated and duplicate vertices dropped; a
// notch goes to the nearest point of the outline, at its nearest vertex when within 0.5 mm,
// else at a vertex added there (with a note); "Cut N" text sets the cut count; the
// first other text on layer 1 names the piece (else the block name).
// Landmarks, seams and bindings are not in DXF: a sidecar JSON adds them
// (ApplySidecar in pattern_json.h). Malformed files throw InputError naming
// the file and the line.
//
// Writing (atomic) produces R12 ASCII with the ASTM layers (or AAMA's), the
// pieces laid out side by side; the sew line is the outline, the cut line is
// the outline offset by the seam allowance.
#ifndef BESPOKE_RESIZE_IO_PATTERN_DXF_H_
#define BESPOKE_RESIZE_IO_PATTERN_DXF_H_

#include <filesystem>
#include <string>

#include "resize/pattern/pattern.h"

namespace bespoke {

enum class DxfFlavor { kAstm, kAama };

struct DxfWriteOptions {
  DxfFlavor flavor = DxfFlavor::kAstm;  // default ASTM D6673 layers
  double seam_allowance_mm = 10;        // cut line offset; default 10 mm
  double gap_mm = 40;                   // layout gap between pieces; default 40 mm
  void Check() const;
};

std::string PatternToDxf(const DxfWriteOptions& options, const Pattern& pattern);
void WritePatternDxf(const DxfWriteOptions& options, const Pattern& pattern,
                     const std::filesystem::path& file);

// Pieces only (no seams or bindings); validated.
Pattern PatternFromDxf(const std::string& text, const std::string& what);
Pattern ReadPatternDxf(const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_PATTERN_DXF_H_
