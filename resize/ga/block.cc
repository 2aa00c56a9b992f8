#include "resize/ga/block.h"

#include <algorithm>
#include <cmath>

#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

// Sorted grid lines: the bounding box ends plus the critical coordinates,
// lines closer than `merge` folded into the first one (box ends are kept).
std::vector<double> GridLines(std::vector<double> values, double lo, double hi, double merge) {
  std::sort(values.begin(), values.end());
  std::vector<double> lines = {lo};
  for (double v : values)
    if (v - lines.back() >= merge && hi - v >= merge) lines.push_back(v);
  lines.push_back(hi);
  return lines;
}

// A vertex turning less than this lies on its neighbours' chord (rad).
constexpr double kChordRad = 1e-7;

std::pair<int, double> Locate(const std::vector<double>& lines, double v) {
  const int n = static_cast<int>(lines.size());
  int i = static_cast<int>(std::upper_bound(lines.begin(), lines.end(), v) - lines.begin()) - 1;
  i = std::clamp(i, 0, n - 2);
  return {i, (v - lines[i]) / (lines[i + 1] - lines[i])};
}

// Weights on lines i - 1 .. i + 2 of the value at position s of interval i:
// cubic Hermite with Catmull-Rom tangents for uneven spacing (the slope of
// the parabola through the node and its two neighbours; one-sided at the
// grid's ends), linear outside [0, 1].
void Weights1d(const std::vector<double>& lines, int i, double s, double w[4]) {
  const int n = static_cast<int>(lines.size());
  for (int a = 0; a < 4; ++a) w[a] = 0;
  if (s < 0 || s > 1) {
    w[1] = 1 - s;
    w[2] = s;
    return;
  }
  const double h = lines[i + 1] - lines[i];
  // Tangent at node k as weights on nodes k - 1, k, k + 1 (offsets into w).
  auto tangent = [&](int k, double scale, int at) {
    const bool left = k > 0, right = k + 1 < n;
    if (left && right) {
      const double hl = lines[k] - lines[k - 1], hr = lines[k + 1] - lines[k];
      w[at - 1] += scale * -hr / (hl * (hl + hr));
      w[at] += scale * (hr / hl - hl / hr) / (hl + hr);
      w[at + 1] += scale * hl / (hr * (hl + hr));
    } else if (right) {
      const double hr = lines[k + 1] - lines[k];
      w[at] -= scale / hr;
      w[at + 1] += scale / hr;
    } else {
      const double hl = lines[k] - lines[k - 1];
      w[at - 1] -= scale / hl;
      w[at] += scale / hl;
    }
  };
  const double s2 = s * s, s3 = s2 * s;
  w[1] += 2 * s3 - 3 * s2 + 1;
  w[2] += -2 * s3 + 3 * s2;
  tangent(i, h * (s3 - 2 * s2 + s), 1);
  tangent(i + 1, h * (s3 - s2), 2);
}

GridParam Param(const std::vector<double>& xs, const std::vector<double>& ys,
                const Eigen::Vector2d& p) {
  GridParam g;
  std::tie(g.i, g.s) = Locate(xs, p.x());
  std::tie(g.j, g.t) = Locate(ys, p.y());
  g.i0 = g.i - 1;
  g.j0 = g.j - 1;
  Weights1d(xs, g.i, g.s, g.wx);
  Weights1d(ys, g.j, g.t, g.wy);
  for (double* w : {g.wx, g.wy})
    for (int a = 0; a < 4; ++a)
      if (std::abs(w[a]) < 1e-15) w[a] = 0;
  return g;
}

}  // namespace

std::vector<StraightRun> KeptStraightRuns(const Piece& piece) {
  std::vector<StraightRun> runs = piece.straight;
  const int n = piece.num_vertices();
  std::vector<bool> on_run(n, false);
  for (const StraightRun& r : piece.straight)
    for (int v = r.from;; v = (v + 1) % n) {
      on_run[v] = true;
      if (v == r.to) break;
    }
  const Eigen::VectorXd turning = TurningAngles(piece.outline);
  auto chord_point = [&](int v) { return !on_run[v] && std::abs(turning[v]) < kChordRad; };
  for (int v = 0; v < n; ++v) {
    if (!chord_point(v) || chord_point((v - 1 + n) % n)) continue;
    int end = v;
    for (int k = 0; k < n && chord_point(end); ++k) end = (end + 1) % n;
    if (end != (v - 1 + n) % n) runs.push_back({(v - 1 + n) % n, end, false});
  }
  return runs;
}

BlockSet BuildBlocks(const BlockOptions& options, const Pattern& pattern) {
  BlockSet set;
  for (const Piece& piece : pattern.pieces) {
    Block block;
    const Eigen::Vector2d lo = piece.outline.colwise().minCoeff().transpose();
    const Eigen::Vector2d hi = piece.outline.colwise().maxCoeff().transpose();
    std::vector<double> cx, cy;
    for (int c : piece.critical) {
      cx.push_back(piece.outline(c, 0));
      cy.push_back(piece.outline(c, 1));
    }
    const std::vector<double> xs = GridLines(cx, lo.x(), hi.x(), options.merge_mm);
    const std::vector<double> ys = GridLines(cy, lo.y(), hi.y(), options.merge_mm);
    block.nu = static_cast<int>(xs.size());
    block.nv = static_cast<int>(ys.size());
    block.offset = set.num_genes;
    block.extent_x = hi.x() - lo.x();
    block.extent_y = hi.y() - lo.y();
    block.xs = xs;
    block.ys = ys;
    for (int v = 0; v < piece.num_vertices(); ++v)
      block.outline.push_back(Param(xs, ys, piece.outline.row(v).transpose()));
    for (int l = 0; l < static_cast<int>(piece.landmarks.size()); ++l)
      block.inside.push_back(Param(xs, ys, piece.LandmarkPosition(l)));
    if (piece.has_grain)
      block.grain = {Param(xs, ys, piece.grain_start), Param(xs, ys, piece.grain_end)};
    for (const Outline& line : piece.internal_lines) {
      std::vector<GridParam> params;
      for (Eigen::Index r = 0; r < line.rows(); ++r)
        params.push_back(Param(xs, ys, line.row(r).transpose()));
      block.internal_lines.push_back(params);
    }
    // Runs kept straight, split at their critical vertices: between those a
    // run stretches evenly (its inner vertices keep their fractions of the
    // chord); the critical vertices themselves follow the grid, and the
    // constraints keep them on the run's line (FitnessModel::Constraints).
    std::vector<bool> critical(piece.num_vertices(), false);
    for (int c : piece.critical) critical[c] = true;
    const int n = piece.num_vertices();
    for (const StraightRun& r : KeptStraightRuns(piece)) {
      int from = r.from;
      for (int v = (r.from + 1) % n;; v = (v + 1) % n) {
        if (v != r.to && !critical[v]) continue;
        BlockRun run{from, v, {}, {}};
        const Eigen::Vector2d a = piece.outline.row(from),
                              d = Eigen::Vector2d(piece.outline.row(v)) - a;
        for (int w = (from + 1) % n; w != v; w = (w + 1) % n) {
          run.inner.push_back(w);
          run.t.push_back((Eigen::Vector2d(piece.outline.row(w)) - a).dot(d) /
                          std::max(d.squaredNorm(), 1e-12));
        }
        if (!run.inner.empty()) block.straight.push_back(std::move(run));
        from = v;
        if (v == r.to) break;
      }
    }
    set.num_genes += 2 * block.nu * block.nv;
    set.base_genes.conservativeResize(set.num_genes);
    for (int j = 0; j < block.nv; ++j)
      for (int i = 0; i < block.nu; ++i) {
        set.base_genes[block.offset + 2 * (j * block.nu + i)] = xs[i];
        set.base_genes[block.offset + 2 * (j * block.nu + i) + 1] = ys[j];
      }
    set.blocks.push_back(std::move(block));
  }
  return set;
}

Eigen::Vector2d EvalParam(const Block& b, const double* genes, const GridParam& p) {
  const double* g = genes + b.offset;
  double x = 0, y = 0;
  for (int c = 0; c < 4; ++c) {
    if (p.wy[c] == 0) continue;
    const int row = (p.j0 + c) * b.nu + p.i0;  // zero weights mark nodes beyond the grid
    double rx = 0, ry = 0;
    for (int a = 0; a < 4; ++a) {
      if (p.wx[a] == 0) continue;
      rx += p.wx[a] * g[2 * (row + a)];
      ry += p.wx[a] * g[2 * (row + a) + 1];
    }
    x += p.wy[c] * rx;
    y += p.wy[c] * ry;
  }
  return {x, y};
}

void ParamStencil(const Block& b, const GridParam& p, std::vector<std::pair<int, double>>* out) {
  out->clear();
  for (int c = 0; c < 4; ++c)
    for (int a = 0; a < 4; ++a)
      if (p.wx[a] != 0 && p.wy[c] != 0)
        out->push_back({b.offset / 2 + (p.j0 + c) * b.nu + p.i0 + a, p.wx[a] * p.wy[c]});
}

void EvalOutline(const Block& block, const double* genes, Outline* out) {
  const int n = static_cast<int>(block.outline.size());
  out->resize(n, 2);
  for (int v = 0; v < n; ++v) out->row(v) = EvalParam(block, genes, block.outline[v]).transpose();
  for (const BlockRun& r : block.straight) {
    const Eigen::RowVector2d a = out->row(r.from), d = out->row(r.to) - a;
    for (size_t k = 0; k < r.inner.size(); ++k) out->row(r.inner[k]) = a + r.t[k] * d;
  }
}

Pattern ApplyGenes(const Pattern& base, const BlockSet& blocks, const Eigen::VectorXd& genes) {
  Pattern result = base;
  for (size_t k = 0; k < base.pieces.size(); ++k) {
    const Block& b = blocks.blocks[k];
    Piece& piece = result.pieces[k];
    EvalOutline(b, genes.data(), &piece.outline);
    for (size_t l = 0; l < piece.landmarks.size(); ++l)
      if (piece.landmarks[l].vertex < 0)
        piece.landmarks[l].position = EvalParam(b, genes.data(), b.inside[l]);
    if (piece.has_grain) {
      piece.grain_start = EvalParam(b, genes.data(), b.grain[0]);
      piece.grain_end = EvalParam(b, genes.data(), b.grain[1]);
    }
    for (size_t l = 0; l < piece.internal_lines.size(); ++l)
      for (size_t r = 0; r < b.internal_lines[l].size(); ++r)
        piece.internal_lines[l].row(r) =
            EvalParam(b, genes.data(), b.internal_lines[l][r]).transpose();
  }
  return result;
}

bool RowOrdered(const Block& b, const double* genes, int row, double min_gap_mm) {
  const double* g = genes + b.offset;
  for (int i = 0; i + 1 < b.nu; ++i)
    if (g[2 * (row * b.nu + i + 1)] - g[2 * (row * b.nu + i)] < min_gap_mm) return false;
  return true;
}

bool ColumnOrdered(const Block& b, const double* genes, int column, double min_gap_mm) {
  const double* g = genes + b.offset;
  for (int j = 0; j + 1 < b.nv; ++j)
    if (g[2 * ((j + 1) * b.nu + column) + 1] - g[2 * (j * b.nu + column) + 1] < min_gap_mm)
      return false;
  return true;
}

bool BlockValid(const Block& b, const double* genes, double min_gap_mm) {
  for (int j = 0; j < b.nv; ++j)
    if (!RowOrdered(b, genes, j, min_gap_mm)) return false;
  for (int i = 0; i < b.nu; ++i)
    if (!ColumnOrdered(b, genes, i, min_gap_mm)) return false;
  return true;
}

}  // namespace bespoke
