// DXF writer (R12 ASCII, ASTM D6673 / AAMA layers). See pattern_dxf.h.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "resize/io/pattern_dxf.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

class Writer {
 public:
  void Code(int code, const std::string& value) { out_ << Pad(code) << "\n" << value << "\n"; }
  void Code(int code, int value) { Code(code, std::to_string(value)); }
  void Real(int code, double value) {
    char buffer[48];
    std::snprintf(buffer, sizeof(buffer), "%.6f", value);
    Code(code, buffer);
  }
  std::string str() const { return out_.str(); }

 private:
  static std::string Pad(int code) {
    std::string s = std::to_string(code);
    return std::string(s.size() < 3 ? 3 - s.size() : 0, ' ') + s;
  }
  std::ostringstream out_;
};

std::string BlockName(const std::string& name, int index) {
  std::string s;
  for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) ? std::toupper(c) : '_';
  if (s.empty()) s = "PIECE";
  return s + "_" + std::to_string(index + 1);
}

void Polyline(Writer& w, const std::string& layer, const Outline& o, bool closed) {
  w.Code(0, "POLYLINE");
  w.Code(8, layer);
  w.Code(66, 1);
  w.Real(10, 0);
  w.Real(20, 0);
  w.Real(30, 0);
  w.Code(70, closed ? 1 : 0);
  for (Eigen::Index i = 0; i < o.rows(); ++i) {
    w.Code(0, "VERTEX");
    w.Code(8, layer);
    w.Real(10, o(i, 0));
    w.Real(20, o(i, 1));
    w.Real(30, 0);
  }
  w.Code(0, "SEQEND");
  w.Code(8, layer);
}

void Line(Writer& w, const std::string& layer, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  w.Code(0, "LINE");
  w.Code(8, layer);
  w.Real(10, a.x());
  w.Real(20, a.y());
  w.Real(30, 0);
  w.Real(11, b.x());
  w.Real(21, b.y());
  w.Real(31, 0);
}

void Text(Writer& w, const Eigen::Vector2d& at, const std::string& text) {
  w.Code(0, "TEXT");
  w.Code(8, "1");
  w.Real(10, at.x());
  w.Real(20, at.y());
  w.Real(30, 0);
  w.Real(40, 5);
  w.Code(1, text);
}

void Header(Writer& w, const std::vector<std::string>& layers) {
  w.Code(999, "Bespoke pattern export (DXF-AAMA/ASTM layers, mm)");
  w.Code(0, "SECTION");
  w.Code(2, "HEADER");
  w.Code(9, "$ACADVER");
  w.Code(1, "AC1009");
  w.Code(9, "$INSBASE");
  w.Real(10, 0);
  w.Real(20, 0);
  w.Real(30, 0);
  w.Code(9, "$MEASUREMENT");
  w.Code(70, 1);
  w.Code(0, "ENDSEC");
  w.Code(0, "SECTION");
  w.Code(2, "TABLES");
  w.Code(0, "TABLE");
  w.Code(2, "LTYPE");
  w.Code(70, 1);
  w.Code(0, "LTYPE");
  w.Code(2, "CONTINUOUS");
  w.Code(70, 0);
  w.Code(3, "Solid line");
  w.Code(72, 65);
  w.Code(73, 0);
  w.Real(40, 0);
  w.Code(0, "ENDTAB");
  w.Code(0, "TABLE");
  w.Code(2, "LAYER");
  w.Code(70, static_cast<int>(layers.size()));
  for (const std::string& layer : layers) {
    w.Code(0, "LAYER");
    w.Code(2, layer);
    w.Code(70, 0);
    w.Code(62, 7);
    w.Code(6, "CONTINUOUS");
  }
  w.Code(0, "ENDTAB");
  w.Code(0, "TABLE");
  w.Code(2, "STYLE");
  w.Code(70, 1);
  w.Code(0, "STYLE");
  w.Code(2, "STANDARD");
  w.Code(70, 0);
  w.Real(40, 0);
  w.Real(41, 1);
  w.Real(50, 0);
  w.Code(71, 0);
  w.Real(42, 2.5);
  w.Code(3, "txt");
  w.Code(4, "");
  w.Code(0, "ENDTAB");
  w.Code(0, "ENDSEC");
}

void PieceBlock(const DxfWriteOptions& o, Writer& w, const Piece& piece, const std::string& name,
                const Eigen::Vector2d& shift) {
  auto moved = [&](const Outline& line) {
    Outline m = line;
    m.rowwise() += shift.transpose();
    return m;
  };
  w.Code(0, "BLOCK");
  w.Code(8, "1");
  w.Code(2, name);
  w.Code(70, 0);
  w.Real(10, 0);
  w.Real(20, 0);
  w.Real(30, 0);
  w.Code(3, name);
  const Outline sew = moved(piece.outline);
  Polyline(w, "1", o.seam_allowance_mm > 0 ? OffsetOutline(sew, o.seam_allowance_mm) : sew, true);
  Polyline(w, o.flavor == DxfFlavor::kAstm ? "14" : "8", sew, true);
  for (const Outline& line : piece.internal_lines) Polyline(w, "8", moved(line), false);
  const int n = piece.num_vertices();
  const double sign = SignedArea(piece.outline) >= 0 ? 1 : -1;
  for (int i : piece.notches) {
    const Eigen::Vector2d d =
        (Eigen::Vector2d(sew.row((i + 1) % n)) - Eigen::Vector2d(sew.row((i - 1 + n) % n)))
            .normalized();
    const Eigen::Vector2d inward(-d.y() * sign, d.x() * sign);
    const Eigen::Vector2d at = sew.row(i).transpose();
    if (o.flavor == DxfFlavor::kAstm) {
      w.Code(0, "POINT");
      w.Code(8, "4");
      w.Real(10, at.x());
      w.Real(20, at.y());
      w.Real(30, 5);  // notch length, as Valentina writes it
      w.Real(50, std::atan2(inward.y(), inward.x()) * 180 / M_PI);
    } else {
      Line(w, "4", at, at + 5 * inward);
    }
  }
  if (piece.has_grain) Line(w, "7", piece.grain_start + shift, piece.grain_end + shift);
  const Eigen::Vector2d centre = sew.colwise().mean().transpose();
  Text(w, centre, piece.name);
  Text(w, centre - Eigen::Vector2d(0, 8), "Cut " + std::to_string(piece.cut_count));
  w.Code(0, "ENDBLK");
  w.Code(8, "1");
}

}  // namespace

void DxfWriteOptions::Check() const {
  if (seam_allowance_mm < 0 || gap_mm < 0)
    throw InputError("DXF options: seam allowance and gap must be >= 0");
}

std::string PatternToDxf(const DxfWriteOptions& options, const Pattern& pattern) {
  options.Check();
  Writer w;
  const std::vector<std::string> layers =
      options.flavor == DxfFlavor::kAstm ? std::vector<std::string>{"0", "1", "4", "7", "8", "14"}
                                         : std::vector<std::string>{"0", "1", "4", "7", "8"};
  Header(w, layers);
  w.Code(0, "SECTION");
  w.Code(2, "BLOCKS");
  std::vector<std::string> names;
  double x = 0;
  for (size_t k = 0; k < pattern.pieces.size(); ++k) {
    const Piece& piece = pattern.pieces[k];
    const Eigen::Vector2d lo = piece.outline.colwise().minCoeff().transpose();
    const Eigen::Vector2d hi = piece.outline.colwise().maxCoeff().transpose();
    const Eigen::Vector2d shift(x + options.seam_allowance_mm - lo.x(),
                                options.seam_allowance_mm - lo.y());
    x += hi.x() - lo.x() + 2 * options.seam_allowance_mm + options.gap_mm;
    names.push_back(BlockName(piece.name, static_cast<int>(k)));
    PieceBlock(options, w, piece, names.back(), shift);
  }
  w.Code(0, "ENDSEC");
  w.Code(0, "SECTION");
  w.Code(2, "ENTITIES");
  for (const std::string& name : names) {
    w.Code(0, "INSERT");
    w.Code(8, "1");
    w.Code(2, name);
    w.Real(10, 0);
    w.Real(20, 0);
    w.Real(30, 0);
  }
  w.Code(0, "ENDSEC");
  w.Code(0, "EOF");
  return w.str();
}

void WritePatternDxf(const DxfWriteOptions& options, const Pattern& pattern,
                     const std::filesystem::path& file) {
  WriteFileAtomically(file, PatternToDxf(options, pattern));
}

}  // namespace bespoke
