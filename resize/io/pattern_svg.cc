#include "resize/io/pattern_svg.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "resize/pattern/geometry.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/xml_escape.h"

namespace bespoke {
namespace {

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2f", v);
  return buffer;
}

struct Placement {
  Eigen::Vector2d offset;  // svg = (x + offset.x, offset.y - y)
};

std::string Path(const Outline& o, const Placement& at, bool closed) {
  std::ostringstream s;
  for (Eigen::Index i = 0; i < o.rows(); ++i)
    s << (i == 0 ? "M" : "L") << Num(o(i, 0) + at.offset.x()) << "," << Num(at.offset.y() - o(i, 1))
      << " ";
  if (closed) s << "Z";
  return s.str();
}

Eigen::Vector2d ToSvg(const Eigen::Vector2d& p, const Placement& at) {
  return {p.x() + at.offset.x(), at.offset.y() - p.y()};
}

void DrawPiece(const SvgOptions& options, const Piece& piece, const Placement& at,
               std::ostream& out) {
  out << "  <g id=\"" << XmlEscape(piece.name) << "\">\n";
  if (options.seam_allowance_mm > 0)
    out << "    <path d=\""
        << Path(OffsetOutline(piece.outline, options.seam_allowance_mm), at, true)
        << "\" fill=\"none\" stroke=\"black\" stroke-width=\"0.4\" stroke-dasharray=\"4 2\"/>\n";
  out << "    <path d=\"" << Path(piece.outline, at, true)
      << "\" fill=\"#f4f4f4\" stroke=\"black\" stroke-width=\"0.6\"/>\n";
  for (const Outline& line : piece.internal_lines)
    out << "    <path d=\"" << Path(line, at, false)
        << "\" fill=\"none\" stroke=\"#555\" stroke-width=\"0.4\"/>\n";
  const double sign = SignedArea(piece.outline) >= 0 ? 1 : -1;
  const int n = piece.num_vertices();
  for (int i : piece.notches) {
    const Eigen::Vector2d prev = piece.outline.row((i - 1 + n) % n),
                          next = piece.outline.row((i + 1) % n);
    const Eigen::Vector2d d = (next - prev).normalized();
    const Eigen::Vector2d outward(d.y() * sign, -d.x() * sign);
    const Eigen::Vector2d a = ToSvg(piece.outline.row(i), at),
                          b = ToSvg(Eigen::Vector2d(piece.outline.row(i)) + 6 * outward, at);
    out << "    <line x1=\"" << Num(a.x()) << "\" y1=\"" << Num(a.y()) << "\" x2=\"" << Num(b.x())
        << "\" y2=\"" << Num(b.y()) << "\" stroke=\"black\" stroke-width=\"0.6\"/>\n";
  }
  if (piece.has_grain) {
    const Eigen::Vector2d a = ToSvg(piece.grain_start, at), b = ToSvg(piece.grain_end, at);
    const Eigen::Vector2d d = (b - a).normalized(), n2(-d.y(), d.x());
    const Eigen::Vector2d h1 = b - 8 * d + 3 * n2, h2 = b - 8 * d - 3 * n2;
    out << "    <path d=\"M" << Num(a.x()) << "," << Num(a.y()) << " L" << Num(b.x()) << ","
        << Num(b.y()) << " M" << Num(h1.x()) << "," << Num(h1.y()) << " L" << Num(b.x()) << ","
        << Num(b.y()) << " L" << Num(h2.x()) << "," << Num(h2.y())
        << "\" fill=\"none\" stroke=\"black\" stroke-width=\"0.5\"/>\n";
  }
  const Eigen::Vector2d centre = ToSvg(piece.outline.colwise().mean().transpose(), at);
  std::string cut = "cut " + std::to_string(piece.cut_count);
  if (piece.mirrored) cut += " (mirrored pairs)";
  if (piece.on_fold) cut += " on fold";
  out << "    <text x=\"" << Num(centre.x()) << "\" y=\"" << Num(centre.y())
      << "\" font-family=\"sans-serif\" font-size=\"8\" text-anchor=\"middle\">"
      << XmlEscape(piece.name) << "</text>\n";
  out << "    <text x=\"" << Num(centre.x()) << "\" y=\"" << Num(centre.y() + 10)
      << "\" font-family=\"sans-serif\" font-size=\"5\" text-anchor=\"middle\">" << XmlEscape(cut)
      << "</text>\n  </g>\n";
}

}  // namespace

void SvgOptions::Check() const {
  if (seam_allowance_mm < 0 || gap_mm < 0 || row_width_mm <= 0)
    throw InputError("SVG options: seam allowance and gap must be >= 0, row width > 0");
}

std::string PatternToSvg(const SvgOptions& options, const Pattern& pattern) {
  options.Check();
  const double margin = options.seam_allowance_mm + options.gap_mm;
  std::vector<Placement> places;
  double x = margin, y = margin + 120, row_height = 0, width = 0;  // 120 mm: title + test square
  for (const Piece& piece : pattern.pieces) {
    const Eigen::Vector2d lo = piece.outline.colwise().minCoeff(),
                          hi = piece.outline.colwise().maxCoeff();
    const double w = hi.x() - lo.x(), h = hi.y() - lo.y();
    if (x > margin && x + w > options.row_width_mm) {
      x = margin;
      y += row_height + 2 * margin;
      row_height = 0;
    }
    places.push_back({Eigen::Vector2d(x - lo.x(), y + hi.y())});
    x += w + 2 * margin;
    width = std::max(width, x);
    row_height = std::max(row_height, h);
  }
  const double height = y + row_height + margin;
  width = std::max(width, 300.0);
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(width) << "mm\" height=\""
      << Num(height) << "mm\" viewBox=\"0 0 " << Num(width) << " " << Num(height) << "\">\n"
      << "  <title>" << XmlEscape(pattern.name) << "</title>\n"
      << "  <text x=\"" << Num(margin) << "\" y=\"" << Num(margin)
      << "\" font-family=\"sans-serif\" font-size=\"10\">" << XmlEscape(pattern.name)
      << " - 1:1, millimetres; sew lines solid, cut lines dashed ("
      << Num(options.seam_allowance_mm) << " mm allowance)</text>\n"
      << "  <rect x=\"" << Num(margin) << "\" y=\"" << Num(margin + 8)
      << "\" width=\"100\" height=\"100\" fill=\"none\" stroke=\"black\" stroke-width=\"0.4\"/>\n"
      << "  <text x=\"" << Num(margin + 50) << "\" y=\"" << Num(margin + 60)
      << "\" font-family=\"sans-serif\" font-size=\"6\" text-anchor=\"middle\">100 mm</text>\n";
  for (size_t i = 0; i < pattern.pieces.size(); ++i)
    DrawPiece(options, pattern.pieces[i], places[i], out);
  out << "</svg>\n";
  return out.str();
}

void WritePatternSvg(const SvgOptions& options, const Pattern& pattern,
                     const std::filesystem::path& file) {
  WriteFileAtomically(file, PatternToSvg(options, pattern));
}

}  // namespace bespoke
