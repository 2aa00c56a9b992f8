#include "resize/ga/block.h"

#include <algorithm>

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

std::pair<int, double> Locate(const std::vector<double>& lines, double v) {
  const int n = static_cast<int>(lines.size());
  int i = static_cast<int>(std::upper_bound(lines.begin(), lines.end(), v) - lines.begin()) - 1;
  i = std::clamp(i, 0, n - 2);
  return {i, (v - lines[i]) / (lines[i + 1] - lines[i])};
}

GridParam Param(const std::vector<double>& xs, const std::vector<double>& ys,
                const Eigen::Vector2d& p) {
  GridParam g;
  std::tie(g.i, g.s) = Locate(xs, p.x());
  std::tie(g.j, g.t) = Locate(ys, p.y());
  return g;
}

}  // namespace

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
    for (const StraightRun& r : piece.straight) {
      BlockRun run{r.from, r.to, {}, {}};
      const Eigen::Vector2d a = piece.outline.row(r.from),
                            d = Eigen::Vector2d(piece.outline.row(r.to)) - a;
      for (int v = (r.from + 1) % piece.num_vertices(); v != r.to;
           v = (v + 1) % piece.num_vertices()) {
        run.inner.push_back(v);
        run.t.push_back((Eigen::Vector2d(piece.outline.row(v)) - a).dot(d) /
                        std::max(d.squaredNorm(), 1e-12));
      }
      if (!run.inner.empty()) block.straight.push_back(std::move(run));
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
  const int k00 = 2 * (p.j * b.nu + p.i), k10 = k00 + 2, k01 = k00 + 2 * b.nu, k11 = k01 + 2;
  const double w00 = (1 - p.s) * (1 - p.t), w10 = p.s * (1 - p.t), w01 = (1 - p.s) * p.t,
               w11 = p.s * p.t;
  return {w00 * g[k00] + w10 * g[k10] + w01 * g[k01] + w11 * g[k11],
          w00 * g[k00 + 1] + w10 * g[k10 + 1] + w01 * g[k01 + 1] + w11 * g[k11 + 1]};
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
