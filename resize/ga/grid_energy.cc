#include "resize/ga/grid_energy.h"

#include <cmath>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Builds rows as sums of weighted control-point coordinates.
class Rows {
 public:
  explicit Rows(Triplets* t) : t_(t) {}
  int Next() { return rows_++; }
  void Add(int row, int gene, double w) { t_->emplace_back(row, gene, w); }
  int count() const { return rows_; }

 private:
  Triplets* t_;
  int rows_ = 0;
};

// Gene of coordinate `c` (0 x, 1 y) of control point (i, j) of `b`.
int Gene(const Block& b, int i, int j, int c) { return b.offset + 2 * (j * b.nu + i) + c; }

// Adds w x (strain of edge e1 - strain of edge e2) for coordinate c, where an
// edge is (i, j, di, dj, length): (P(i + di, j + dj) - P(i, j)) / length.
struct Edge {
  int i, j, di, dj;
  double length;
};
void StrainTerm(const Block& b, Rows* rows, const Edge& e, double w, int c, int row) {
  rows->Add(row, Gene(b, e.i + e.di, e.j + e.dj, c), w / e.length);
  rows->Add(row, Gene(b, e.i, e.j, c), -w / e.length);
}

void BlockRows(const GridEnergyOptions& o, const Block& b, Rows* rows) {
  const int nu = b.nu, nv = b.nv;
  auto h = [&](int i, int j) { return Edge{i, j, 1, 0, b.xs[i + 1] - b.xs[i]}; };
  auto v = [&](int i, int j) { return Edge{i, j, 0, 1, b.ys[j + 1] - b.ys[j]}; };
  auto difference = [&](const Edge& e1, const Edge& e2, double w) {
    for (int c = 0; c < 2; ++c) {
      const int row = rows->Next();
      StrainTerm(b, rows, e1, w, c, row);
      StrainTerm(b, rows, e2, -w, c, row);
    }
  };
  const double rect = std::sqrt(o.rectilinear_weight);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i + 2 < nu; ++i) difference(h(i, j), h(i + 1, j), 1);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j + 2 < nv; ++j) difference(v(i, j), v(i, j + 1), 1);
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) difference(h(i, j), h(i, j + 1), rect);
  for (int i = 0; i + 1 < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) difference(v(i, j), v(i + 1, j), rect);
  const double shear = std::sqrt(o.shear_weight), prior = std::sqrt(o.prior_weight);
  const int iso = rows->Next();
  const double nh = nv * (nu - 1), nvv = nu * (nv - 1);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      StrainTerm(b, rows, h(i, j), shear, 1, rows->Next());
      StrainTerm(b, rows, h(i, j), std::sqrt(o.isotropy_weight) / nh, 0, iso);
      for (int c = 0; c < 2; ++c) StrainTerm(b, rows, h(i, j), prior, c, rows->Next());
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) {
      StrainTerm(b, rows, v(i, j), shear, 0, rows->Next());
      StrainTerm(b, rows, v(i, j), -std::sqrt(o.isotropy_weight) / nvv, 1, iso);
      for (int c = 0; c < 2; ++c) StrainTerm(b, rows, v(i, j), prior, c, rows->Next());
    }
  const double anchor = std::sqrt(o.anchor_weight) / (nu * nv);
  for (int c = 0; c < 2; ++c) {
    const int row = rows->Next();
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) rows->Add(row, Gene(b, i, j, c), anchor);
  }
}

}  // namespace

void GridEnergyOptions::Check() const {
  if (!(rectilinear_weight >= 0) || !(shear_weight >= 0) || !(isotropy_weight >= 0) ||
      !(prior_weight > 0) || !(anchor_weight > 0))
    throw InputError("grid energy options: weights >= 0, prior and anchor > 0");
}

void GridEnergy(const GridEnergyOptions& o, const BlockSet& blocks, const std::vector<bool>& active,
                Eigen::SparseMatrix<double>* s, Eigen::VectorXd* target) {
  o.Check();
  Triplets triplets;
  Rows rows(&triplets);
  for (size_t k = 0; k < blocks.blocks.size(); ++k)
    if (active[k]) BlockRows(o, blocks.blocks[k], &rows);
  s->resize(rows.count(), blocks.num_genes);
  s->setFromTriplets(triplets.begin(), triplets.end());
  *target = *s * blocks.base_genes;
}

}  // namespace bespoke
