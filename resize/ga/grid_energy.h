// How far a set of control grids is from a smooth grade of the base: the
// quadratic energy the graded start minimises and the polish uses to spread
// a correction (grader.h, polish.h).
//
// For a block with base grid lines xs (#nu) and ys (#nv), interval widths
// W_i and heights H_j, and control points P(i, j) (mm), the strain of a
// horizontal grid edge is a_ij = (P(i+1, j) - P(i, j)) / W_i and of a
// vertical one b_ij = (P(i, j+1) - P(i, j)) / H_j (2-vectors; the base grid
// has a = (1, 0), b = (0, 1)). The residuals, all linear in the genes, are
//   along a row / a column: a_ij - a_i+1,j and b_ij - b_i,j+1   (smooth stretch)
//   across rows / columns:  a_ij - a_i,j+1 and b_ij - b_i+1,j   x rectilinear_weight
//   shear: a_ij.y and b_ij.x                                    x shear_weight
//   per block: mean a.x - mean b.y                              x isotropy_weight
//   every strain minus its base value                           x prior_weight
//   per block: mean control point minus its base mean (mm)      x anchor_weight
// (weights enter squared energies, so residuals carry their square roots).
// A rectilinear grade (grid lines moved as a whole, grader.h) has zero
// across-row, across-column and shear terms; a grade that must change a
// side seam's suppression spreads that change smoothly over the grid.
#ifndef BESPOKE_RESIZE_GA_GRID_ENERGY_H_
#define BESPOKE_RESIZE_GA_GRID_ENERGY_H_

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "resize/ga/block.h"

namespace bespoke {

struct GridEnergyOptions {
  double rectilinear_weight = 1;  // across rows / columns alike. Default 1.
  double shear_weight = 0.1;      // grid edges keep their direction. Default 0.1.
  double isotropy_weight = 0.01;  // a block's x and y stretch alike. Default 0.01.
  double prior_weight = 1e-4;     // strains stay at their base value. Default 1e-4.
  double anchor_weight = 1e-6;    // a block's mean position stays (per mm). Default 1e-6.
  void Check() const;             // InputError for negative weights or prior / anchor <= 0
};

// Residual rows r = S genes - target over the blocks whose `active` flag is
// set (one per block), columns for every gene (#genes); target = S base
// genes, so the base grids have zero energy. The energy of a change from
// other grids x0 (#genes) is |S (genes - x0)|^2, i.e. target = S x0.
void GridEnergy(const GridEnergyOptions& options, const BlockSet& blocks,
                const std::vector<bool>& active, Eigen::SparseMatrix<double>* s,
                Eigen::VectorXd* target);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_GRID_ENERGY_H_
