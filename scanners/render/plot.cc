#include "scanners/render/plot.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr std::array<std::array<double, 3>, 8> kPalette = {{{0.12, 0.47, 0.71},
                                                            {0.89, 0.47, 0.14},
                                                            {0.17, 0.63, 0.17},
                                                            {0.84, 0.15, 0.16},
                                                            {0.58, 0.40, 0.74},
                                                            {0.55, 0.34, 0.29},
                                                            {0.89, 0.47, 0.76},
                                                            {0.50, 0.50, 0.50}}};

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool valid() const { return lo <= hi; }
};

// Maps data to device coordinates inside the plot rectangle.
struct Axes {
  double left, top, width, height;
  Range x, y;  // in transformed (log10 where log) units
  bool log_x, log_y;
  double Tx(double v) const { return log_x ? std::log10(v) : v; }
  double Ty(double v) const { return log_y ? std::log10(v) : v; }
  double X(double v) const { return left + (Tx(v) - x.lo) / (x.hi - x.lo) * width; }
  double Y(double v) const { return top + height - (Ty(v) - y.lo) / (y.hi - y.lo) * height; }
};

std::string FormatTick(double v) {
  if (std::abs(v) < 1e-12) return "0";
  char buffer[32];
  const double a = std::abs(v);
  if (a >= 1e6 || a < 1e-3) {
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    std::string text = buffer;  // "1e+06" -> "1e6", "2.5e-05" -> "2.5e-5"
    for (const char* from : {"e+0", "e+", "e-0"}) {
      const auto at = text.find(from);
      if (at != std::string::npos) {
        text.replace(at, std::string(from).size(), std::string(from) == "e-0" ? "e-" : "e");
        break;
      }
    }
    return text;
  } else {
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
  }
  return buffer;
}

bool Usable(double x, double y, bool log_x, bool log_y) {
  return std::isfinite(x) && std::isfinite(y) && (!log_x || x > 0) && (!log_y || y > 0);
}

void CheckChart(const Chart& chart) {
  for (const Series& s : chart.series) {
    if (s.x.size() != s.y.size()) {
      throw InputError("chart '" + chart.title + "': series '" + s.label + "' has " +
                       std::to_string(s.x.size()) + " x values but " + std::to_string(s.y.size()) +
                       " y values");
    }
    if (chart.log_y && s.style == Series::Style::kBars) {
      throw InputError("chart '" + chart.title + "': bars need a linear y axis");
    }
  }
  if (chart.width_px < 100 || chart.height_px < 100) {
    throw InputError("chart '" + chart.title + "': size must be at least 100 x 100");
  }
}

// Data ranges in transformed units, padded, with bars' baseline included.
void FitRanges(const Chart& chart, Axes* axes) {
  Range x, y;
  for (const Series& s : chart.series) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!Usable(s.x[i], s.y[i], chart.log_x, chart.log_y)) continue;
      const double half = s.style == Series::Style::kBars ? 0.5 * s.bar_width : 0.0;
      x.Add(axes->Tx(s.x[i] - half));
      x.Add(axes->Tx(s.x[i] + half));
      y.Add(axes->Ty(s.y[i]));
      if (s.style == Series::Style::kBars) y.Add(0.0);
    }
  }
  if (!x.valid()) x = {0, 1};
  if (!y.valid()) y = {0, 1};
  if (chart.x_min < chart.x_max) x = {axes->Tx(chart.x_min), axes->Tx(chart.x_max)};
  if (chart.y_min < chart.y_max) y = {axes->Ty(chart.y_min), axes->Ty(chart.y_max)};
  auto pad = [](Range* r) {
    const double span = r->hi - r->lo;
    const double p = span > 0 ? 0.04 * span : (std::abs(r->lo) > 0 ? 0.1 * std::abs(r->lo) : 1.0);
    r->lo -= p;
    r->hi += p;
  };
  if (!(chart.x_min < chart.x_max)) pad(&x);
  if (!(chart.y_min < chart.y_max)) pad(&y);
  axes->x = x;
  axes->y = y;
}

// Tick values in data units for one axis.
std::vector<double> AxisTicks(const Range& r, bool log, int target) {
  if (!log) return NiceTicks(r.lo, r.hi, target);
  std::vector<double> ticks;
  const int first = static_cast<int>(std::ceil(r.lo)), last = static_cast<int>(std::floor(r.hi));
  const bool fine = last - first < 3;
  for (int k = first - 1; k <= last; ++k) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (!fine && m != 1.0) continue;
      const double v = m * std::pow(10.0, k);
      if (std::log10(v) >= r.lo && std::log10(v) <= r.hi) ticks.push_back(v);
    }
  }
  return ticks;
}

void SetColor(cairo_t* cr, const std::array<double, 3>& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c[0], c[1], c[2], alpha);
}

void ShowText(cairo_t* cr, const std::string& text, double x, double y, double align_x,
              double align_y) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y - align_y * e.height - e.y_bearing);
  cairo_show_text(cr, text.c_str());
}

void DrawAxes(cairo_t* cr, const Chart& chart, const Axes& a) {
  cairo_set_line_width(cr, 1.0);
  cairo_set_font_size(cr, 12);
  for (double t : AxisTicks(a.x, chart.log_x, 8)) {
    const double px = a.X(t);
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, px, a.top);
    cairo_line_to(cr, px, a.top + a.height);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    ShowText(cr, FormatTick(t), px, a.top + a.height + 6, 0.5, 0.0);
  }
  for (double t : AxisTicks(a.y, chart.log_y, 6)) {
    const double py = a.Y(t);
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, a.left, py);
    cairo_line_to(cr, a.left + a.width, py);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    ShowText(cr, FormatTick(t), a.left - 6, py, 1.0, 0.5);
  }
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_rectangle(cr, a.left, a.top, a.width, a.height);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 13);
  ShowText(cr, chart.x_label, a.left + a.width / 2, a.top + a.height + 28, 0.5, 0.0);
  cairo_save(cr);
  cairo_translate(cr, a.left - 62, a.top + a.height / 2);
  cairo_rotate(cr, -M_PI / 2);
  ShowText(cr, chart.y_label, 0, 0, 0.5, 0.5);
  cairo_restore(cr);
  cairo_set_font_size(cr, 16);
  ShowText(cr, chart.title, a.left + a.width / 2, 14, 0.5, 0.0);
}

void DrawSeries(cairo_t* cr, const Chart& chart, const Axes& a, const Series& s,
                const std::array<double, 3>& color) {
  cairo_save(cr);
  cairo_rectangle(cr, a.left, a.top, a.width, a.height);
  cairo_clip(cr);
  SetColor(cr, color);
  const bool line = s.style == Series::Style::kLine || s.style == Series::Style::kLinePoints;
  const bool points = s.style == Series::Style::kPoints || s.style == Series::Style::kLinePoints;
  if (s.style == Series::Style::kBars) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!Usable(s.x[i], s.y[i], chart.log_x, false)) continue;
      const double x0 = a.X(s.x[i] - 0.5 * s.bar_width), x1 = a.X(s.x[i] + 0.5 * s.bar_width);
      const double y0 = a.Y(0.0), y1 = a.Y(s.y[i]);
      cairo_rectangle(cr, x0, std::min(y0, y1), x1 - x0, std::abs(y1 - y0));
    }
    SetColor(cr, color, 0.75);
    cairo_fill(cr);
  }
  if (line) {
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
    cairo_set_line_width(cr, 2.0);
    bool pen_down = false;
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!Usable(s.x[i], s.y[i], chart.log_x, chart.log_y)) {
        pen_down = false;
        continue;
      }
      if (pen_down)
        cairo_line_to(cr, a.X(s.x[i]), a.Y(s.y[i]));
      else
        cairo_move_to(cr, a.X(s.x[i]), a.Y(s.y[i]));
      pen_down = true;
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  if (points) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!Usable(s.x[i], s.y[i], chart.log_x, chart.log_y)) continue;
      cairo_arc(cr, a.X(s.x[i]), a.Y(s.y[i]), 3.5, 0, 2 * M_PI);
      cairo_fill(cr);
    }
  }
  cairo_restore(cr);
}

void DrawLegend(cairo_t* cr, const Axes& a, const std::vector<const Series*>& series,
                const std::vector<std::array<double, 3>>& colors) {
  cairo_set_font_size(cr, 12);
  double width = 0;
  int rows = 0;
  for (const Series* s : series) {
    if (s->label.empty()) continue;
    cairo_text_extents_t e;
    cairo_text_extents(cr, s->label.c_str(), &e);
    width = std::max(width, e.x_advance);
    ++rows;
  }
  if (rows == 0) return;
  const double box_w = width + 40, box_h = rows * 18 + 8;
  const double x0 = a.left + a.width - box_w - 8, y0 = a.top + 8;
  cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
  cairo_rectangle(cr, x0, y0, box_w, box_h);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.7, 0.7, 0.7);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  int row = 0;
  for (size_t i = 0; i < series.size(); ++i) {
    if (series[i]->label.empty()) continue;
    const double y = y0 + 13 + 18 * row++;
    SetColor(cr, colors[i]);
    cairo_rectangle(cr, x0 + 8, y - 5, 18, 6);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    ShowText(cr, series[i]->label, x0 + 32, y - 2, 0.0, 0.5);
  }
}

void Draw(cairo_t* cr, const Chart& chart) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  Axes a{90.0,        40.0,       chart.width_px - 110.0, chart.height_px - 100.0, {}, {},
         chart.log_x, chart.log_y};
  // Bars without an explicit width take 80 % of their x spacing.
  std::vector<Series> resolved = chart.series;
  for (Series& s : resolved) {
    if (s.style == Series::Style::kBars && s.bar_width <= 0) {
      double spacing = std::numeric_limits<double>::infinity();
      for (size_t i = 1; i < s.x.size(); ++i)
        spacing = std::min(spacing, std::abs(s.x[i] - s.x[i - 1]));
      s.bar_width = std::isfinite(spacing) && spacing > 0 ? 0.8 * spacing : 1.0;
    }
  }
  Chart fitted = chart;
  fitted.series = resolved;
  FitRanges(fitted, &a);
  DrawAxes(cr, chart, a);
  std::vector<const Series*> drawn;
  std::vector<std::array<double, 3>> colors;
  size_t next = 0;
  for (const Series& s : resolved) {
    const auto color = s.color[0] >= 0 ? s.color : kPalette[next++ % kPalette.size()];
    DrawSeries(cr, chart, a, s, color);
    drawn.push_back(&s);
    colors.push_back(color);
  }
  DrawLegend(cr, a, drawn, colors);
}

cairo_status_t AppendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::vector<double> NiceTicks(double lo, double hi, int target_count) {
  std::vector<double> ticks;
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi) || target_count < 1) return ticks;
  const double raw = (hi - lo) / target_count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

Series HistogramSeries(const std::vector<double>& values, int bins, const std::string& label,
                       double lo, double hi) {
  if (bins < 1) throw InputError("histogram '" + label + "': needs at least one bin");
  if (!(lo < hi)) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (double v : values) {
      if (std::isfinite(v)) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    if (!(lo <= hi)) lo = 0, hi = 1;
    if (lo == hi) lo -= 0.5, hi += 0.5;
  }
  const double width = (hi - lo) / bins;
  Series s;
  s.label = label;
  s.style = Series::Style::kBars;
  s.bar_width = 0.9 * width;
  s.y.assign(static_cast<size_t>(bins), 0.0);
  for (int b = 0; b < bins; ++b) s.x.push_back(lo + (b + 0.5) * width);
  for (double v : values) {
    if (!std::isfinite(v) || v < lo || v > hi) continue;
    const int b = std::min(bins - 1, static_cast<int>((v - lo) / width));
    s.y[static_cast<size_t>(b)] += 1.0;
  }
  return s;
}

void WriteChart(const Chart& chart, const std::filesystem::path& file) {
  CheckChart(chart);
  const std::string ext = file.extension().string();
  std::string bytes;
  if (ext == ".png") {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, chart.width_px, chart.height_px),
        &cairo_surface_destroy);
    cairo_t* cr = cairo_create(surface.get());
    Draw(cr, chart);
    cairo_destroy(cr);
    if (cairo_surface_write_to_png_stream(surface.get(), &AppendToString, &bytes) !=
        CAIRO_STATUS_SUCCESS) {
      throw InternalError("cairo could not encode " + file.string());
    }
  } else if (ext == ".svg") {
    cairo_surface_t* surface = cairo_svg_surface_create_for_stream(&AppendToString, &bytes,
                                                                   chart.width_px, chart.height_px);
    cairo_t* cr = cairo_create(surface);
    Draw(cr, chart);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    cairo_surface_destroy(surface);
  } else {
    throw InputError(file, "charts are written as .png or .svg, not '" + ext + "'");
  }
  WriteFileAtomically(file, bytes);
}

}  // namespace bespoke
