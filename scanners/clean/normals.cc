#include "scanners/clean/normals.h"

#include <omp.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr std::uint8_t kEmpty = 0, kSolid = 1, kOutside = 2;

// Occupancy grid of the body, dilated, sealed below the feet, with the
// outside flood-filled.
class ExteriorGrid {
 public:
  ExteriorGrid(const NormalOptions& options, const Eigen::MatrixX3d& points) {
    const Eigen::Vector3d low = points.colwise().minCoeff().transpose();
    const Eigen::Vector3d high = points.colwise().maxCoeff().transpose();
    cell_ = options.grid_cell_mm;
    const double margin = options.probe_mm + options.hole_close_mm + 2 * cell_;
    Eigen::Vector3d size = (high - low).array() + 2 * margin;
    // Keep the grid under 64M cells whatever the cloud's extent.
    const double cells = (size / cell_).prod();
    if (cells > 64e6) cell_ *= std::cbrt(cells / 64e6);
    origin_ = low.array() - margin;
    for (int c = 0; c < 3; ++c) n_[c] = static_cast<int>(std::ceil(size(c) / cell_)) + 1;
    state_.assign(static_cast<size_t>(n_[0]) * n_[1] * n_[2], kEmpty);
    MarkSolid(options, points, low.z());
    FloodOutside();
  }

  double cell() const { return cell_; }

  bool Outside(const Eigen::Vector3d& p) const {
    int i[3];
    for (int c = 0; c < 3; ++c) {
      i[c] = static_cast<int>(std::floor((p(c) - origin_(c)) / cell_));
      if (i[c] < 0 || i[c] >= n_[c]) return true;
    }
    return state_[Index(i[0], i[1], i[2])] == kOutside;
  }

 private:
  size_t Index(int x, int y, int z) const {
    return (static_cast<size_t>(z) * n_[1] + static_cast<size_t>(y)) * n_[0] +
           static_cast<size_t>(x);
  }

  void MarkSolid(const NormalOptions& options, const Eigen::MatrixX3d& points, double lowest_z) {
    std::vector<std::uint8_t> occupied(state_.size(), 0);
    std::vector<size_t> cells;
    for (Eigen::Index r = 0; r < points.rows(); ++r) {
      int i[3];
      for (int c = 0; c < 3; ++c)
        i[c] = static_cast<int>(std::floor((points(r, c) - origin_(c)) / cell_));
      const size_t idx = Index(i[0], i[1], i[2]);
      if (!occupied[idx]) occupied[idx] = 1, cells.push_back(idx);
    }
    const int reach = static_cast<int>(std::ceil(options.hole_close_mm / cell_));
    const double reach2 = (options.hole_close_mm / cell_) * (options.hole_close_mm / cell_);
    std::vector<int> offsets[3];
    for (int dz = -reach; dz <= reach; ++dz) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          if (dx * dx + dy * dy + dz * dz > reach2 + 1e-9) continue;
          offsets[0].push_back(dx), offsets[1].push_back(dy), offsets[2].push_back(dz);
        }
      }
    }
    const size_t plane = static_cast<size_t>(n_[0]) * n_[1];
    for (size_t idx : cells) {
      const int x = static_cast<int>(idx % n_[0]);
      const int y = static_cast<int>((idx / n_[0]) % n_[1]);
      const int z = static_cast<int>(idx / plane);
      for (size_t o = 0; o < offsets[0].size(); ++o) {
        const int xx = x + offsets[0][o], yy = y + offsets[1][o], zz = z + offsets[2][o];
        if (xx < 0 || yy < 0 || zz < 0 || xx >= n_[0] || yy >= n_[1] || zz >= n_[2]) continue;
        state_[Index(xx, yy, zz)] = kSolid;
      }
    }
    // The seal: every layer whose centre is below the lowest point.
    for (int z = 0; z < n_[2]; ++z) {
      if (origin_.z() + (z + 0.5) * cell_ >= lowest_z) break;
      std::fill(state_.begin() + static_cast<std::ptrdiff_t>(z * plane),
                state_.begin() + static_cast<std::ptrdiff_t>((z + 1) * plane), kSolid);
    }
  }

  void FloodOutside() {
    std::deque<size_t> queue;
    auto visit = [&](int x, int y, int z) {
      if (x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) return;
      const size_t idx = Index(x, y, z);
      if (state_[idx] != kEmpty) return;
      state_[idx] = kOutside;
      queue.push_back(idx);
    };
    for (int z = 0; z < n_[2]; ++z) {
      for (int y = 0; y < n_[1]; ++y) {
        for (int x = 0; x < n_[0]; ++x) {
          if (x == 0 || y == 0 || z == 0 || x == n_[0] - 1 || y == n_[1] - 1 || z == n_[2] - 1) {
            visit(x, y, z);
          }
        }
      }
    }
    const size_t plane = static_cast<size_t>(n_[0]) * n_[1];
    while (!queue.empty()) {
      const size_t idx = queue.front();
      queue.pop_front();
      const int x = static_cast<int>(idx % n_[0]);
      const int y = static_cast<int>((idx / n_[0]) % n_[1]);
      const int z = static_cast<int>(idx / plane);
      visit(x - 1, y, z), visit(x + 1, y, z), visit(x, y - 1, z);
      visit(x, y + 1, z), visit(x, y, z - 1), visit(x, y, z + 1);
    }
  }

  double cell_;
  Eigen::Vector3d origin_;
  int n_[3];
  std::vector<std::uint8_t> state_;
};

Eigen::Vector3d AwayFromAxis(const Eigen::Vector3d& p) {
  const Eigen::Vector3d radial(p.x(), p.y(), 0.0);
  return radial.norm() > 1e-9 ? radial.normalized() : Eigen::Vector3d::UnitY();
}

// Unoriented plane-fit normals; false in `ok` where there are too few neighbours.
void FitNormals(const NormalOptions& options, const Eigen::MatrixX3d& points,
                const NeighbourLists& neighbours, Eigen::MatrixX3d* normals,
                std::vector<char>* ok) {
  const Eigen::Index n = points.rows();
  normals->resize(n, 3);
  ok->assign(static_cast<size_t>(n), 0);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Vector3d sum = points.row(i).transpose();
    Eigen::Matrix3d outer = sum * sum.transpose();
    int count = 1;
    for (int j = 0; j < options.k; ++j) {
      const int other = neighbours.at(i, j);
      if (other < 0) break;
      const Eigen::Vector3d q = points.row(other).transpose();
      sum += q;
      outer += q * q.transpose();
      ++count;
    }
    if (count < 3) {
      normals->row(i) = AwayFromAxis(points.row(i).transpose()).transpose();
      continue;
    }
    const Eigen::Vector3d mean = sum / count;
    const Eigen::Matrix3d covariance = outer / count - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    normals->row(i) = solver.eigenvectors().col(0).normalized().transpose();
    (*ok)[static_cast<size_t>(i)] = 1;
  }
}

// A point inside the torso: 60 % of the way up (body frame, z up), at the
// median x of the points 55-65 % up and half way between the front-most and
// back-most of those within 60 mm of that median (the midline strip: arms
// held in front are lateral). If the flood fill reached it, the body's inside
// leaked into the "outside" through a hole wider than the closing, and both
// probe directions leave the shell at about the same distance.
Eigen::Vector3d TorsoInside(const Eigen::MatrixX3d& points) {
  const double low = points.col(2).minCoeff(), high = points.col(2).maxCoeff();
  std::vector<Eigen::Index> band;
  std::vector<double> xs;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double t = (points(i, 2) - low) / std::max(1e-9, high - low);
    if (t >= 0.55 && t <= 0.65) band.push_back(i), xs.push_back(points(i, 0));
  }
  const double z = low + 0.6 * (high - low);
  if (xs.empty()) return Eigen::Vector3d(0, 0, z);
  std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(xs.size() / 2), xs.end());
  const double x = xs[xs.size() / 2];
  double front = -std::numeric_limits<double>::infinity(), back = -front;
  for (const Eigen::Index i : band)
    if (std::abs(points(i, 0) - x) <= 60)
      front = std::max(front, points(i, 1)), back = std::min(back, points(i, 1));
  return Eigen::Vector3d(x, std::isfinite(front) ? 0.5 * (front + back) : 0.0, z);
}

// Step 1: +1 / -1 where the exterior test decides, 0 where it does not. The
// closing grows by 10 mm (the probe with it) while the torso's inside is
// flooded, up to 3 times; `closing_mm` gets the closing used.
std::vector<signed char> ExteriorVotes(const NormalOptions& options, const Eigen::MatrixX3d& points,
                                       const Eigen::MatrixX3d& normals, double* closing_mm) {
  NormalOptions o = options;
  const Eigen::Vector3d inside = TorsoInside(points);
  auto grid = std::make_unique<ExteriorGrid>(o, points);
  for (int attempt = 0; attempt < 3 && grid->Outside(inside); ++attempt) {
    o.probe_mm *= (o.hole_close_mm + 10) / std::max(1.0, o.hole_close_mm);
    o.hole_close_mm += 10;
    grid = std::make_unique<ExteriorGrid>(o, points);
  }
  *closing_mm = o.hole_close_mm;
  const double step = grid->cell() / 2;
  const int steps = static_cast<int>(std::ceil(o.probe_mm / step));
  std::vector<signed char> vote(static_cast<size_t>(points.rows()), 0);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = points.row(i).transpose();
    const Eigen::Vector3d n = normals.row(i).transpose();
    for (int s = 1; s <= steps; ++s) {
      const bool out_plus = grid->Outside(p + s * step * n);
      const bool out_minus = grid->Outside(p - s * step * n);
      if (out_plus != out_minus) {
        vote[static_cast<size_t>(i)] = out_plus ? 1 : -1;
        break;
      }
      if (out_plus) break;  // both sides outside at the same distance: undecided
    }
  }
  return vote;
}

}  // namespace

void NormalOptions::Check() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw InputError("normal option out of range: " + what);
  };
  require(k >= 3 && k <= 100, "k must be 3..100");
  require(grid_cell_mm >= 1 && grid_cell_mm <= 100, "grid_cell_mm must be 1..100");
  require(hole_close_mm >= 0 && hole_close_mm <= 200, "hole_close_mm must be 0..200");
  require(probe_mm > hole_close_mm && probe_mm <= 500, "probe_mm must be in (hole_close_mm, 500]");
}

OrientedNormals EstimateOutwardNormals(const NormalOptions& options,
                                       const Eigen::MatrixX3d& body_points,
                                       const NeighbourLists& neighbours) {
  options.Check();
  BESPOKE_CHECK(neighbours.k >= options.k, "neighbour lists shorter than the normal k");
  BESPOKE_CHECK(neighbours.num_points() == body_points.rows(),
                "neighbour lists do not match the points");
  OrientedNormals result;
  const Eigen::Index n = body_points.rows();
  if (n == 0) {
    result.normals.resize(0, 3);
    return result;
  }
  std::vector<char> fitted;
  FitNormals(options, body_points, neighbours, &result.normals, &fitted);

  std::vector<signed char> vote =
      ExteriorVotes(options, body_points, result.normals, &result.report.closing_mm);
  std::vector<char> decided(static_cast<size_t>(n), 0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto u = static_cast<size_t>(i);
    if (!fitted[u]) {
      ++result.report.degenerate;
      decided[u] = 1;  // already the fallback direction
    } else if (vote[u] != 0) {
      if (vote[u] < 0) result.normals.row(i) *= -1.0;
      decided[u] = 1;
      ++result.report.by_exterior;
    }
  }

  // Step 2: agree with decided neighbours, sweep after sweep.
  std::vector<Eigen::Index> undecided;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!decided[static_cast<size_t>(i)]) undecided.push_back(i);
  }
  while (!undecided.empty()) {
    std::vector<std::pair<Eigen::Index, bool>> now;  // point, flip
    std::vector<Eigen::Index> still;
    for (Eigen::Index i : undecided) {
      double agreement = 0.0;
      for (int j = 0; j < options.k; ++j) {
        const int other = neighbours.at(i, j);
        if (other < 0) break;
        if (decided[static_cast<size_t>(other)])
          agreement += result.normals.row(i).dot(result.normals.row(other));
      }
      if (agreement != 0.0) {
        now.emplace_back(i, agreement < 0);
      } else {
        still.push_back(i);
      }
    }
    if (now.empty()) break;
    for (const auto& [i, flip] : now) {
      if (flip) result.normals.row(i) *= -1.0;
      decided[static_cast<size_t>(i)] = 1;
    }
    result.report.by_propagation += static_cast<std::int64_t>(now.size());
    undecided.swap(still);
  }

  // Step 3: what nothing reached points away from the vertical axis.
  for (Eigen::Index i : undecided) {
    const Eigen::Vector3d away = AwayFromAxis(body_points.row(i).transpose());
    if (result.normals.row(i).dot(away) < 0) result.normals.row(i) *= -1.0;
    ++result.report.by_fallback;
  }
  return result;
}

}  // namespace bespoke
