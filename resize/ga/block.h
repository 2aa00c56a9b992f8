// Blocks (thesis 4.1.2, Fig 4.4): for every piece a rectangular control grid
// whose lines pass through the piece's critical points and its bounding box;
// every point of the piece (outline vertices, inside landmarks, grain-line
// ends, internal lines) is stored once as (cell, s, t) parameters of that grid,
// and is reconstructed from the control points by the block surface: the
// tensor-product cubic Hermite interpolant of the control grid with
// Catmull-Rom tangents for uneven spacing (each point a fixed weighted sum
// of the 4 x 4 control points around its cell). Deviation: the thesis's
// block surface is not specified beyond (u, v) parameters; a bilinear one
// kinks every curve where it crosses a grid line when neighbouring cells
// stretch differently, which puts new inflections into smooth curves. This
// surface is C1, reproduces affine maps exactly (a scaled grid scales the
// piece) and interpolates the nodes, so critical points, which sit on grid
// nodes, move exactly with their control point. Points outside the grid
// (an inside landmark or grain end beyond the outline's box) are
// extrapolated bilinearly from the nearest cell.
//
// The gene of an individual (Eq 4.1) is all blocks' control points in one
// vector: block k's point (i, j) (column i along x, row j along y) has its x
// at genes[offset_k + 2 * (j * nu_k + i)] and its y right after (mm).
#ifndef BESPOKE_RESIZE_GA_BLOCK_H_
#define BESPOKE_RESIZE_GA_BLOCK_H_

#include <Eigen/Core>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

struct GridParam {
  int i = 0, j = 0;     // cell: between columns i, i+1 and rows j, j+1
  double s = 0, t = 0;  // position in the cell along x and y (may leave [0, 1] outside the grid)
  // The point = sum over a, b in 0..3 of wx[a] wy[b] control point (i0 + a, j0 + b);
  // i0 = i - 1, j0 = j - 1, clamped into the grid with zero weights beyond it.
  int i0 = 0, j0 = 0;
  double wx[4] = {0, 0, 0, 0}, wy[4] = {0, 0, 0, 0};
};

// A stretch of a straight run of the piece (pattern.h StraightRun) between two
// of its critical vertices: its inner vertices are placed on the chord
// between its ends at their base parameters, so it stays straight whatever
// the control points do.
struct BlockRun {
  int from = 0, to = 0;    // outline indices of the ends
  std::vector<int> inner;  // outline indices of the inner vertices
  std::vector<double> t;   // their parameters along the chord (0 = from, 1 = to)
};

struct Block {
  int nu = 0, nv = 0;              // control points along x (columns) and y (rows)
  int offset = 0;                  // index of this block's first gene
  std::vector<GridParam> outline;  // one per outline vertex
  std::vector<GridParam> inside;   // one per landmark (used for inside landmarks)
  std::vector<GridParam> grain;    // 0 or 2 (start, end)
  std::vector<std::vector<GridParam>> internal_lines;
  double extent_x = 0, extent_y = 0;  // bounding box size of the base piece (mm)
  std::vector<double> xs, ys;         // base grid lines (nu and nv of them, mm)
  std::vector<BlockRun> straight;     // straight runs kept straight by EvalOutline
};

struct BlockSet {
  std::vector<Block> blocks;  // one per pattern piece, same order
  int num_genes = 0;
  Eigen::VectorXd base_genes;  // the control grid of the base pattern (mm)
};

struct BlockOptions {
  // Grid lines closer than this are merged into one (mm). Default 5 mm.
  double merge_mm = 5;
};

// The runs of `piece` that resizing keeps straight: its straight runs
// (pattern.h, the design's straight edges and folds) and every other chain
// of collinear vertices (turning below 1e-7 rad; points an importer added on
// an edge, lines drafted as several points), walking forward from the last
// vertex before the chain to the first after it.
std::vector<StraightRun> KeptStraightRuns(const Piece& piece);

// Builds the blocks of `pattern` (which must validate).
BlockSet BuildBlocks(const BlockOptions& options, const Pattern& pattern);

// The block surface at `p` for the control grid of `block` in `genes` (mm).
Eigen::Vector2d EvalParam(const Block& block, const double* genes, const GridParam& p);

// The control points `p` depends on and their weights: (index of the
// control point in the whole gene vector, counting points, i.e. gene / 2;
// weight). The point's x is the weighted sum of those points' x, its y of
// their y. Zero weights are left out.
void ParamStencil(const Block& block, const GridParam& p, std::vector<std::pair<int, double>>* out);

// Writes the outline of `block` for `genes` into `out` (#V x 2, resized);
// inner vertices of straight runs are put back on their chords.
void EvalOutline(const Block& block, const double* genes, Outline* out);

// The pattern with every piece reshaped by `genes` (outlines, inside
// landmarks, grain lines, internal lines); seams and bindings are copied.
Pattern ApplyGenes(const Pattern& base, const BlockSet& blocks, const Eigen::VectorXd& genes);

// Ordering rule of Algorithm 8: along every row x increases and along every
// column y increases by at least `min_gap_mm`, so the grid never folds over.
bool RowOrdered(const Block& block, const double* genes, int row, double min_gap_mm);
bool ColumnOrdered(const Block& block, const double* genes, int column, double min_gap_mm);
bool BlockValid(const Block& block, const double* genes, double min_gap_mm);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_BLOCK_H_
