// Blocks (thesis 4.1.2, Fig 4.4): for every piece a rectangular control grid
// whose lines pass through the piece's critical points and its bounding box;
// every point of the piece (outline vertices, inside landmarks, grain-line
// ends, internal lines) is stored once as (cell, s, t) parameters of that grid,
// and is reconstructed from the control points by bilinear interpolation in
// its cell. Moving control points reshapes the piece; critical points sit on
// grid nodes, so they move exactly with their control point.
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
  double s = 0, t = 0;  // bilinear weights along x and y (may leave [0, 1] outside the grid)
};

// A straight run of the piece (pattern.h StraightRun): its inner vertices are
// placed on the chord between its end vertices at their base parameters, so
// the run stays straight whatever the control points do.
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

// Builds the blocks of `pattern` (which must validate).
BlockSet BuildBlocks(const BlockOptions& options, const Pattern& pattern);

// Bilinear evaluation of `p` on the control grid of `block` in `genes`.
Eigen::Vector2d EvalParam(const Block& block, const double* genes, const GridParam& p);

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
