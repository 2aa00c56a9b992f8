#include "resize/io/pattern_overlay.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr double kMarginPx = 20, kLabelPx = 22, kLegendPx = 28;

// A piece's points in the picture's millimetres: the layer's placement
// applied (or none).
struct Placed {
  Outline outline;
  std::vector<Eigen::Vector2d> landmarks;
  bool has_grain = false;
  Eigen::Vector2d grain_start, grain_end;
  std::vector<Outline> internal;
};

Eigen::Vector2d Apply(const OverlayLayer& layer, const std::string& piece,
                      const Eigen::Vector2d& p) {
  const auto it = layer.placement.find(piece);
  if (it == layer.placement.end()) return p;
  return it->second.leftCols<2>() * p + it->second.col(2);
}

Placed Place(const OverlayLayer& layer, const Piece& piece) {
  Placed out;
  auto apply = [&](const Eigen::Vector2d& p) { return Apply(layer, piece.name, p); };
  out.outline.resize(piece.outline.rows(), 2);
  for (Eigen::Index v = 0; v < piece.outline.rows(); ++v)
    out.outline.row(v) = apply(piece.outline.row(v).transpose()).transpose();
  for (const PieceLandmark& l : piece.landmarks)
    if (l.vertex >= 0) out.landmarks.push_back(apply(piece.outline.row(l.vertex).transpose()));
  out.has_grain = piece.has_grain;
  out.grain_start = apply(piece.grain_start);
  out.grain_end = apply(piece.grain_end);
  for (const Outline& line : piece.internal_lines) {
    Outline l(line.rows(), 2);
    for (Eigen::Index r = 0; r < line.rows(); ++r)
      l.row(r) = apply(line.row(r).transpose()).transpose();
    out.internal.push_back(l);
  }
  return out;
}

struct Cell {
  std::string name;
  std::vector<Placed> layers;  // one per layer; empty outline when the layer lacks the piece
  Eigen::Vector2d lo, hi;      // bounding box of every layer (mm)
  Eigen::Vector2d origin_px;   // top-left corner of the cell in the picture
};

cairo_status_t Append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void DrawCell(cairo_t* cr, const OverlayOptions& o, const std::vector<OverlayLayer>& layers,
              const Cell& cell) {
  const double s = o.px_per_mm;
  auto to_px = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(cell.origin_px.x() + (p.x() - cell.lo.x()) * s,
                           cell.origin_px.y() + kLabelPx + (cell.hi.y() - p.y()) * s);
  };
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_font_size(cr, 13);
  cairo_move_to(cr, cell.origin_px.x(), cell.origin_px.y() + 14);
  cairo_show_text(cr, cell.name.c_str());
  for (size_t k = 0; k < layers.size(); ++k) {
    const Placed& p = cell.layers[k];
    if (p.outline.rows() == 0) continue;
    const OverlayLayer& layer = layers[k];
    cairo_set_source_rgb(cr, layer.color[0], layer.color[1], layer.color[2]);
    cairo_set_line_width(cr, layer.line_px);
    const double dash[] = {6, 4};
    cairo_set_dash(cr, dash, layer.dashed ? 2 : 0, 0);
    for (Eigen::Index v = 0; v < p.outline.rows(); ++v) {
      const Eigen::Vector2d q = to_px(p.outline.row(v).transpose());
      v == 0 ? cairo_move_to(cr, q.x(), q.y()) : cairo_line_to(cr, q.x(), q.y());
    }
    cairo_close_path(cr);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 0.6 * layer.line_px);
    for (const Outline& line : p.internal) {
      for (Eigen::Index r = 0; r < line.rows(); ++r) {
        const Eigen::Vector2d q = to_px(line.row(r).transpose());
        r == 0 ? cairo_move_to(cr, q.x(), q.y()) : cairo_line_to(cr, q.x(), q.y());
      }
      cairo_stroke(cr);
    }
    if (p.has_grain) {
      const Eigen::Vector2d a = to_px(p.grain_start), b = to_px(p.grain_end);
      cairo_move_to(cr, a.x(), a.y());
      cairo_line_to(cr, b.x(), b.y());
      cairo_stroke(cr);
    }
    cairo_set_dash(cr, dash, 0, 0);
    if (o.landmarks)
      for (const Eigen::Vector2d& l : p.landmarks) {
        const Eigen::Vector2d q = to_px(l);
        cairo_arc(cr, q.x(), q.y(), 1.5 + layer.line_px, 0, 2 * M_PI);
        cairo_fill(cr);
      }
  }
}

void DrawLegend(cairo_t* cr, const std::vector<OverlayLayer>& layers, double px_per_mm) {
  double x = kMarginPx;
  const double y = kMarginPx + 8;
  cairo_set_font_size(cr, 13);
  for (const OverlayLayer& layer : layers) {
    cairo_set_source_rgb(cr, layer.color[0], layer.color[1], layer.color[2]);
    cairo_set_line_width(cr, layer.line_px + 0.5);
    const double dash[] = {6, 4};
    cairo_set_dash(cr, dash, layer.dashed ? 2 : 0, 0);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + 30, y);
    cairo_stroke(cr);
    cairo_move_to(cr, x + 36, y + 5);
    cairo_show_text(cr, layer.label.c_str());
    cairo_text_extents_t e;
    cairo_text_extents(cr, layer.label.c_str(), &e);
    x += 60 + e.x_advance;
  }
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + 100 * px_per_mm, y);
  cairo_stroke(cr);
  cairo_move_to(cr, x + 100 * px_per_mm + 6, y + 5);
  cairo_show_text(cr, "100 mm");
}

}  // namespace

void OverlayOptions::Check() const {
  if (!(px_per_mm > 0) || !(gap_mm >= 0) || !(row_width_mm > 0))
    throw InputError("overlay options: scale and row width > 0, gap >= 0");
}

void WritePatternOverlay(const OverlayOptions& o, const std::vector<OverlayLayer>& layers,
                         const std::filesystem::path& file) {
  o.Check();
  if (layers.empty()) throw InputError(file, "an overlay needs at least one layer");
  for (const OverlayLayer& layer : layers)
    if (layer.pattern == nullptr)
      throw InputError(file, "overlay layer '" + layer.label + "' has no pattern");
  if (file.extension() != ".png") throw InputError(file, "overlays are written as .png");
  std::vector<std::string> names = o.pieces;
  if (names.empty())
    for (const Piece& piece : layers[0].pattern->pieces) names.push_back(piece.name);
  std::vector<Cell> cells;
  for (const std::string& name : names) {
    Cell cell;
    cell.name = name;
    cell.lo = Eigen::Vector2d::Constant(1e300);
    cell.hi = Eigen::Vector2d::Constant(-1e300);
    for (const OverlayLayer& layer : layers) {
      const int p = layer.pattern->FindPiece(name);
      cell.layers.push_back(p < 0 ? Placed() : Place(layer, layer.pattern->pieces[p]));
      const Outline& outline = cell.layers.back().outline;
      if (outline.rows() == 0) continue;
      cell.lo = cell.lo.cwiseMin(outline.colwise().minCoeff().transpose());
      cell.hi = cell.hi.cwiseMax(outline.colwise().maxCoeff().transpose());
    }
    if (cell.lo.x() <= cell.hi.x()) cells.push_back(std::move(cell));
  }
  if (cells.empty()) throw InputError(file, "no piece of the overlay's layers to draw");
  // Rows of cells, left to right.
  const double s = o.px_per_mm;
  double x = kMarginPx, y = kMarginPx + kLegendPx, row_height = 0, width = 0;
  for (Cell& cell : cells) {
    const Eigen::Vector2d size = (cell.hi - cell.lo) * s;
    if (x > kMarginPx && x + size.x() > kMarginPx + o.row_width_mm * s) {
      x = kMarginPx;
      y += row_height + o.gap_mm * s;
      row_height = 0;
    }
    cell.origin_px = {x, y};
    x += std::max(size.x(), 120.0) + o.gap_mm * s;
    width = std::max(width, x);
    row_height = std::max(row_height, size.y() + kLabelPx);
  }
  const int width_px = static_cast<int>(std::ceil(width + kMarginPx));
  const int height_px = static_cast<int>(std::ceil(y + row_height + kMarginPx));
  if (width_px > 16000 || height_px > 16000)
    throw InputError(file, "overlay picture too large; lower px_per_mm");
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width_px, height_px), &cairo_surface_destroy);
  cairo_t* cr = cairo_create(surface.get());
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  DrawLegend(cr, layers, s);
  for (const Cell& cell : cells) DrawCell(cr, o, layers, cell);
  cairo_destroy(cr);
  std::string bytes;
  if (cairo_surface_write_to_png_stream(surface.get(), &Append, &bytes) != CAIRO_STATUS_SUCCESS)
    throw InternalError("cairo could not encode " + file.string());
  WriteFileAtomically(file, bytes);
}

}  // namespace bespoke
