// Charts for reports and benchmarks: line, point and bar series on linear or
// logarithmic axes, with title, axis labels, ticks and a legend, written to
// PNG or SVG (by the file's extension) atomically. Cairo does the drawing
// inside plot.cc; this header speaks only standard types.
//
//   Chart chart;
//   chart.title = "Convergence"; chart.x_label = "generation"; chart.y_label = "error (mm)";
//   chart.series.push_back({"measurement", gens, errors});
//   WriteChart(chart, "convergence.png");
//
// Failure: InputError when the extension is not .png/.svg or the folder does
// not exist; InputError when a series' x and y differ in length or a log axis
// gets a non-positive value. Non-finite values are skipped.
#ifndef BESPOKE_SCANNERS_RENDER_PLOT_H_
#define BESPOKE_SCANNERS_RENDER_PLOT_H_

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace bespoke {

struct Series {
  enum class Style { kLine, kPoints, kLinePoints, kBars };
  std::string label;      // legend text; empty = not in the legend
  std::vector<double> x;  // data coordinates; for kBars the bar centres
  std::vector<double> y;  // same length as x; for kBars the bar heights (from 0)
  Style style = Style::kLine;
  // RGB 0-1; negative = the next colour of the default palette.
  std::array<double, 3> color = {-1, -1, -1};
  double bar_width = 0;  // kBars: width in x units; 0 = 80 % of the x spacing
  bool dashed = false;   // kLine/kLinePoints: dashed line (reference lines, targets)
};

struct Chart {
  std::string title;
  std::string x_label;  // with units, e.g. "vertices"
  std::string y_label;  // with units, e.g. "time per vertex (us)"
  std::vector<Series> series;
  bool log_x = false;  // base-10 logarithmic axes
  bool log_y = false;
  int width_px = 900;  // PNG size in pixels; SVG in points
  int height_px = 540;
  // Fixed axis ranges; when min >= max (default) the range fits the data.
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
};

// Draws `chart` into `file` (.png or .svg).
void WriteChart(const Chart& chart, const std::filesystem::path& file);

// A histogram of `values` with `bins` equal bins between the data's min and
// max (or [lo, hi] when lo < hi), as a kBars series labelled `label`.
Series HistogramSeries(const std::vector<double>& values, int bins, const std::string& label,
                       double lo = 0, double hi = 0);

// "Nice" tick positions (1, 2, 5 x 10^k steps) covering [lo, hi], about
// `target_count` of them. Exposed for tests.
std::vector<double> NiceTicks(double lo, double hi, int target_count);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_RENDER_PLOT_H_
