#include "measure/cloud_geodesic/cloud_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include "measure/cloud_geodesic/cell_sheets.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {

void CloudGridOptions::Check() const {
  auto bad = [](const std::string& what) { throw InputError("cloud grid: " + what); };
  if (!(cell_size_mm >= 0) || !std::isfinite(cell_size_mm)) bad("cell_size_mm must be >= 0");
  if (!(auto_cell_spacings > 0) || !std::isfinite(auto_cell_spacings))
    bad("auto_cell_spacings must be > 0");
  if (neighbours < 6 || neighbours > 1000) bad("neighbours must be in [6, 1000]");
  if (!(auto_cells_per_diagonal > 0) || !std::isfinite(auto_cells_per_diagonal))
    bad("auto_cells_per_diagonal must be > 0");
  if (!(sheet_gap_mm >= 0) || !std::isfinite(sheet_gap_mm)) bad("sheet_gap_mm must be >= 0");
  if (!(blend_cells >= 0 && blend_cells <= 3)) bad("blend_cells must be in [0, 3]");
  if (min_seed_points < 0 || min_seed_points > 1000) bad("min_seed_points must be in [0, 1000]");
  if (!(max_link_angle_deg > 0 && max_link_angle_deg <= 90))
    bad("max_link_angle_deg must be in (0, 90]");
}

CloudGrid::CloudGrid(const CloudGridOptions& options, const Eigen::MatrixX3d& points,
                     Progress* progress)
    : CloudGrid(options, points, Eigen::MatrixX3d(0, 3), progress) {}

namespace {

// Unit rows of `normals` (#P x 3; zero rows stay zero: no side known), or
// nothing when there are none.
std::optional<Eigen::MatrixX3d> UnitNormals(const Eigen::MatrixX3d& normals, Eigen::Index points) {
  if (normals.rows() == 0) return std::nullopt;
  if (normals.rows() != points)
    throw InputError("cloud grid: " + std::to_string(normals.rows()) + " normals for " +
                     std::to_string(points) + " points");
  Eigen::MatrixX3d unit = normals;
  for (Eigen::Index i = 0; i < unit.rows(); ++i) {
    const double length = unit.row(i).norm();
    if (!std::isfinite(length))
      throw InputError("cloud grid: normal " + std::to_string(i) + " is not finite");
    if (length > 0) unit.row(i) /= length;
  }
  return unit;
}

// A plane through the rows of `around` (#K x 3, mm, nearest first; squared
// distances `d2`, mm^2) within `reach_mm`, or all of them when fewer than 3
// lie that near. Where those lie along a line - one column of a sparse
// scanner's samples, its neighbour columns farther than the reach, as on a
// throat seen at a grazing angle - the line fixes no plane (any one through
// it fits, and a wrong one cuts the node off from the skin beside it), so
// the nearest rows are taken until they span one: their second principal
// spread at least kMinBreadth of the first (variances; a line with 1 mm of
// noise along 20 mm gives 0.03, a patch of skin about 1).
LocalSurface CloseSeed(const Eigen::MatrixX3d& around, const std::vector<double>& d2,
                       double reach_mm) {
  constexpr double kMinBreadth = 0.1;
  Eigen::Index k = 0;
  while (k < static_cast<Eigen::Index>(d2.size()) &&
         d2[static_cast<size_t>(k)] <= reach_mm * reach_mm)
    ++k;
  if (k < 3) return PcaPlane(around);
  for (;; k = std::min(around.rows(), k + std::max<Eigen::Index>(1, k / 8))) {
    double breadth = 0;
    const LocalSurface seed = PcaPlane(around.topRows(k), nullptr, &breadth);
    if (breadth >= kMinBreadth || k == around.rows()) return seed;
  }
}

}  // namespace

CloudGrid::CloudGrid(const CloudGridOptions& options, const Eigen::MatrixX3d& points,
                     const Eigen::MatrixX3d& normals, Progress* progress) {
  options.Check();
  const std::optional<Eigen::MatrixX3d> unit =
      options.use_normals ? UnitNormals(normals, points.rows()) : std::nullopt;
  const Eigen::MatrixX3d* unit_normals = unit ? &*unit : nullptr;
  if (points.rows() < 10)
    throw InputError("cloud grid: need at least 10 points, got " + std::to_string(points.rows()));
  index_ = std::make_unique<PointIndex>(points);  // checks finiteness
  spacing_ = index_->MedianSpacing();
  if (!(spacing_ > 0)) throw InputError("cloud grid: all points coincide");
  const double diagonal = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  cell_ = options.cell_size_mm > 0 ? options.cell_size_mm
                                   : std::max(options.auto_cell_spacings * spacing_,
                                              diagonal / options.auto_cells_per_diagonal);
  const double ratio = cell_ / spacing_;
  neighbours_ = static_cast<int>(std::clamp(ratio * ratio, double(options.neighbours), 1000.0));
  gap_ = options.sheet_gap_mm > 0 ? options.sheet_gap_mm : 2 * index_->SpacingQuantile(0.9);
  blend_ = options.blend_cells * cell_;
  ProgressBegin(progress, "building the geodesic grid", 3);
  BuildCells(points, unit_normals);
  ProgressUpdate(progress, 1);
  FitNodes(options, points, unit_normals);
  ProgressUpdate(progress, 2);
  LinkNodes(options);
  FindComponents();
  if (unit) point_normals_ = *unit;
  ProgressUpdate(progress, 3);
  ProgressEnd(progress);
}

CloudGrid::~CloudGrid() = default;

std::int64_t CloudGrid::KeyOf(const Eigen::Vector3d& x) const {
  std::int64_t c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((x[k] - min_[k]) / cell_)),
                                    0, dims_[k] - 1);
  return c[0] + dims_[0] * (c[1] + dims_[1] * c[2]);  // Eq 3.19
}

void CloudGrid::BuildCells(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d* normals) {
  min_ = points.colwise().minCoeff().transpose();
  const Eigen::Vector3d extent = points.colwise().maxCoeff().transpose() - min_;
  double total = 1;
  for (int k = 0; k < 3; ++k) {
    dims_[k] = static_cast<std::int64_t>(std::floor(extent[k] / cell_)) + 1;
    total *= static_cast<double>(dims_[k]);
  }
  if (total > std::ldexp(1.0, 60))
    throw InputError("cloud grid: cell size " + std::to_string(cell_) +
                     " mm is far too small for the cloud's extent");
  const Eigen::Index n = points.rows();
  std::vector<std::int64_t> keys(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) keys[i] = KeyOf(points.row(i).transpose());
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return keys[a] != keys[b] ? keys[a] < keys[b] : a < b; });
  point_node_.assign(static_cast<size_t>(n), -1);
  node_point_offsets_.assign(1, 0);
  node_points_.reserve(static_cast<size_t>(n));
  cells_.reserve(static_cast<size_t>(n) / 4 + 16);
  for (size_t begin = 0; begin < order.size();) {
    size_t end = begin;
    while (end < order.size() && keys[order[end]] == keys[order[begin]]) ++end;
    const std::int64_t key = keys[order[begin]];
    const auto groups =
        MergeCoplanar(points, normals,
                      SplitSheets(points, normals, order.data() + begin,
                                  static_cast<int>(end - begin), gap_, *index_, keys),
                      gap_);
    cells_[key] = {static_cast<int>(node_cell_.size()), static_cast<int>(groups.size())};
    for (const auto& group : groups) {
      const int node = static_cast<int>(node_cell_.size());
      node_cell_.push_back(key);
      Eigen::Vector3d side = Eigen::Vector3d::Zero();
      for (int p : group) {
        node_points_.push_back(p);
        point_node_[static_cast<size_t>(p)] = node;
        if (normals) side += normals->row(p).transpose();
      }
      if (normals) node_normal_.push_back(side / static_cast<double>(group.size()));
      node_point_offsets_.push_back(static_cast<int>(node_points_.size()));
    }
    begin = end;
  }
}

void CloudGrid::FitNodes(const CloudGridOptions& options, const Eigen::MatrixX3d& points,
                         const Eigen::MatrixX3d* normals) {
  const int nodes = static_cast<int>(node_cell_.size());
  sites_.resize(static_cast<size_t>(nodes));
  surfaces_.resize(static_cast<size_t>(nodes));
  local_spacing_.resize(static_cast<size_t>(nodes));
  std::vector<int> near;
  std::vector<double> d2;
  for (int node = 0; node < nodes; ++node) {
    const int begin = node_point_offsets_[node], end = node_point_offsets_[node + 1];
    Eigen::MatrixX3d own(end - begin, 3);
    for (int i = begin; i < end; ++i) own.row(i - begin) = points.row(node_points_[i]);
    const Eigen::Vector3d mean = own.colwise().mean().transpose();
    index_->Knn(mean, neighbours_, &near, &d2);
    if (normals && node_normal_[node].norm() >= 0.5) {  // the node's side of the surface only
      size_t kept = 0;
      for (size_t i = 0; i < near.size(); ++i)
        if (normals->row(near[i]).dot(node_normal_[node]) >= 0)
          near[kept] = near[i], d2[kept] = d2[i], ++kept;
      if (kept >= 3) near.resize(kept), d2.resize(kept);
    }
    Eigen::MatrixX3d around(static_cast<Eigen::Index>(near.size()), 3);
    for (size_t i = 0; i < near.size(); ++i) around.row(i) = points.row(near[i]);
    // Seed plane from the node's own points (one sheet by construction) when
    // it has at least min_seed_points of them, else from the points within a
    // cell (or the sheet gap, if larger) of it. A plane through a handful of
    // noisy points tilts: a 5-point sliver along a cell's edge can have its
    // "normal" in the tangent plane, link to nothing and leave islands of
    // unreached points.
    double planarity = 1;
    LocalSurface seed;
    if (own.rows() >= std::max(5, options.min_seed_points)) seed = PcaPlane(own, &planarity);
    if (planarity > 0.3) seed = CloseSeed(around, d2, std::max(gap_, cell_));
    surfaces_[node] = FitLocalSurface(options.fit, around, seed, 0.5 * gap_);
    // Local sample spacing: d points cover about pi r^2 around the node.
    local_spacing_[node] =
        d2.empty() ? spacing_ : std::sqrt(d2.back() * kPi / static_cast<double>(d2.size()));
    sites_[node] = surfaces_[node].PlaneAt(mean).point;
  }
}

double CloudGrid::NormalAgreement(int a, const Eigen::Vector3d& pa, int b,
                                  const Eigen::Vector3d& pb) const {
  const Eigen::Vector3d na = surfaces_[static_cast<size_t>(a)].PlaneAt(pa).normal;
  const Eigen::Vector3d nb = surfaces_[static_cast<size_t>(b)].PlaneAt(pb).normal;
  const double dot = na.dot(nb);
  if (node_normal_.empty()) return std::abs(dot);
  const Eigen::Vector3d& sa = node_normal_[static_cast<size_t>(a)];
  const Eigen::Vector3d& sb = node_normal_[static_cast<size_t>(b)];
  if (sa.norm() < 0.5 || sb.norm() < 0.5) return std::abs(dot);  // a node's points disagree
  return (na.dot(sa) < 0) == (nb.dot(sb) < 0) ? dot : -dot;
}

bool CloudGrid::Connected(int a, int b, double cos_max) {
  ++link_stats_.tested;
  const LocalSurface& sa = surfaces_[a];
  const LocalSurface& sb = surfaces_[b];
  const Eigen::Vector3d& pa = sites_[a];
  const Eigen::Vector3d& pb = sites_[b];
  if (NormalAgreement(a, pa, b, pb) < cos_max) {
    ++link_stats_.angle;
    return false;
  }
  // Each site on the other's surface. Across a gap both offsets are about
  // the gap; round a tight fold one fit may extrapolate badly but the other
  // still holds, hence the smaller of the two.
  if (std::min(std::abs(sa.Offset(pb)), std::abs(sb.Offset(pa))) > 0.5 * gap_) {
    ++link_stats_.offset;
    return false;
  }
  // A scan point near the chord's middle (and, on a long link between sparse
  // nodes, near every point a cell apart along it); "near" allows for the
  // local sampling, which is much sparser than the median in places.
  const double reach = std::max(0.6 * gap_, 1.5 * std::max(local_spacing_[a], local_spacing_[b]));
  const int pieces = 2 * std::max(1, static_cast<int>(std::ceil((pb - pa).norm() / (2 * cell_))));
  for (int k = 1; k < pieces; ++k) {
    double d2 = 0;
    index_->Nearest(pa + (pb - pa) * (static_cast<double>(k) / pieces), &d2);
    if (d2 > reach * reach) {
      ++link_stats_.continuity;
      return false;
    }
  }
  ++link_stats_.linked;
  return true;
}

void CloudGrid::LinkNodes(const CloudGridOptions& options) {
  const double cos_max = std::cos(options.max_link_angle_deg * kPi / 180.0);
  cos_max_angle_ = cos_max;
  const int nodes = num_nodes();
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(static_cast<size_t>(nodes) * 8);
  for (int a = 0; a < nodes; ++a) {
    const std::int64_t key = node_cell_[a];
    const std::int64_t c[3] = {key % dims_[0], (key / dims_[0]) % dims_[1],
                               key / (dims_[0] * dims_[1])};
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          // Each unordered pair of cells once: the 13 "forward" offsets.
          if (dz < 0 || (dz == 0 && (dy < 0 || (dy == 0 && dx <= 0)))) continue;
          const std::int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
          if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) continue;
          const auto it = cells_.find(x + dims_[0] * (y + dims_[1] * z));
          if (it == cells_.end()) continue;
          for (int b = it->second.first; b < it->second.first + it->second.second; ++b)
            if (Connected(a, b, cos_max)) pairs.emplace_back(a, b);
        }
  }
  LinkSparseNodes(cos_max, &pairs);
  link_offsets_.assign(static_cast<size_t>(nodes) + 1, 0);
  for (const auto& [a, b] : pairs) ++link_offsets_[a + 1], ++link_offsets_[b + 1];
  for (int i = 0; i < nodes; ++i) link_offsets_[i + 1] += link_offsets_[i];
  link_targets_.resize(pairs.size() * 2);
  std::vector<int> fill(link_offsets_.begin(), link_offsets_.end() - 1);
  for (const auto& [a, b] : pairs) {
    link_targets_[fill[a]++] = b;
    link_targets_[fill[b]++] = a;
  }
}

// Where the scan is sparser than the grid (skin seen at a grazing angle, as
// under the arm), most cells hold one point or none, and the 26-neighbourhood
// leaves nodes with one or two links or none: a graph full of holes, around
// which the wavefront detours (a 13 mm detour on an armpit-to-wrist length).
// Such nodes are also linked to the nodes of cells further out, up to
// kSparseReach local spacings (and 3 cells) away, under the same tests as
// adjacent ones (normals, offsets, scan points all along the chord), so a
// sparse patch is as well connected as a dense one and still never bridges
// an air gap between sheets.
void CloudGrid::LinkSparseNodes(double cos_max, std::vector<std::pair<int, int>>* pairs) {
  constexpr double kSparseReach = 2.0;
  const int nodes = num_nodes();
  const size_t before = pairs->size();
  for (int a = 0; a < nodes; ++a) {
    const double radius = std::min(kSparseReach * local_spacing_[a], 3 * cell_);
    const int span = static_cast<int>(std::ceil(radius / cell_));
    if (span < 2) continue;
    const std::int64_t key = node_cell_[a];
    const std::int64_t c[3] = {key % dims_[0], (key / dims_[0]) % dims_[1],
                               key / (dims_[0] * dims_[1])};
    for (int dz = -span; dz <= span; ++dz)
      for (int dy = -span; dy <= span; ++dy)
        for (int dx = -span; dx <= span; ++dx) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < 2) continue;  // done
          const std::int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
          if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) continue;
          const auto it = cells_.find(x + dims_[0] * (y + dims_[1] * z));
          if (it == cells_.end()) continue;
          for (int b = it->second.first; b < it->second.first + it->second.second; ++b) {
            // Each pair once: tested from the sparser end (ties: lower index).
            const double rb = std::min(kSparseReach * local_spacing_[b], 3 * cell_);
            if (rb > radius || (rb == radius && b < a)) continue;
            if ((sites_[a] - sites_[b]).norm() > radius) continue;
            if (Connected(a, b, cos_max)) pairs->emplace_back(a, b);
          }
        }
  }
  link_stats_.long_links = static_cast<std::int64_t>(pairs->size() - before);
}

int CloudGrid::LocatePoint(const Eigen::Vector3d& x, double* distance_mm, int component) const {
  double d2 = 0;
  int point = index_->Nearest(x, &d2);
  if (component >= 0 &&
      component_[static_cast<size_t>(point_node_[static_cast<size_t>(point)])] != component) {
    std::vector<int> near;
    std::vector<double> near_d2;
    bool found = false;
    for (const int k : {64, 1024}) {
      index_->Knn(x, k, &near, &near_d2);
      for (size_t i = 0; i < near.size() && !found; ++i) {
        const int candidate = point_node_[static_cast<size_t>(near[i])];
        if (component_[static_cast<size_t>(candidate)] == component) {
          point = near[i];
          d2 = near_d2[i];
          found = true;
        }
      }
      if (found) break;
    }
  }
  if (distance_mm) *distance_mm = std::sqrt(d2);
  return point;
}

int CloudGrid::LocateNode(const Eigen::Vector3d& x, double* distance_mm, int component) const {
  return point_node_[static_cast<size_t>(LocatePoint(x, distance_mm, component))];
}

bool CloudGrid::WithinHops(int a, int b, int hops) const {
  if (a == b) return true;
  if (a < 0 || b < 0 || hops <= 0) return false;
  for (const int* l = links_begin(a); l != links_end(a); ++l)
    if (*l == b) return true;
  if (hops == 1) return false;
  // Small breadth-first search; the frontier stays a few hundred nodes.
  std::vector<int> frontier = {a}, seen = {a};
  for (int depth = 1; depth <= hops && !frontier.empty(); ++depth) {
    std::vector<int> next;
    for (const int n : frontier)
      for (const int* l = links_begin(n); l != links_end(n); ++l) {
        if (*l == b) return true;
        if (std::find(seen.begin(), seen.end(), *l) != seen.end()) continue;
        seen.push_back(*l);
        next.push_back(*l);
      }
    frontier.swap(next);
  }
  return false;
}

bool CloudGrid::StepOnSurface(int a, const Eigen::Vector3d& pa, int b,
                              const Eigen::Vector3d& pb) const {
  if (WithinHops(a, b, 2)) return true;
  if (a < 0 || b < 0) return false;
  const LocalSurface& sa = surfaces_[static_cast<size_t>(a)];
  const LocalSurface& sb = surfaces_[static_cast<size_t>(b)];
  if (NormalAgreement(a, pa, b, pb) < cos_max_angle_) return false;
  return std::min(std::abs(sa.Offset(pb)), std::abs(sb.Offset(pa))) <= 0.5 * gap_;
}

void CloudGrid::FindComponents() {
  const int n = num_nodes();
  component_.assign(static_cast<size_t>(n), -1);
  std::vector<Eigen::Index> points;
  std::vector<int> stack;
  for (int start = 0; start < n; ++start) {
    if (component_[start] >= 0) continue;
    const int id = static_cast<int>(points.size());
    points.push_back(0);
    component_[start] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int node = stack.back();
      stack.pop_back();
      points[id] += node_point_offsets_[node + 1] - node_point_offsets_[node];
      for (const int* l = links_begin(node); l != links_end(node); ++l)
        if (component_[*l] < 0) component_[*l] = id, stack.push_back(*l);
    }
  }
  // Renumber by size, largest first.
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return points[x] > points[y]; });
  std::vector<int> rank(points.size());
  component_points_.resize(points.size());
  for (size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = static_cast<int>(r);
    component_points_[r] = points[order[r]];
  }
  for (int& c : component_) c = rank[c];
}

int CloudGrid::WalkToNearest(const Eigen::Vector3d& x, int start) const {
  int current = start;
  for (int step = 0; step < 64; ++step) {
    int best = current;
    double best_d2 = (x - sites_[current]).squaredNorm();
    for (const int* l = links_begin(current); l != links_end(current); ++l) {
      const double d2 = (x - sites_[*l]).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = *l;
    }
    if (best == current) break;
    current = best;
  }
  return current;
}

bool CloudGrid::PlaneAt(const Eigen::Vector3d& position, int* hint, TangentPlane* plane) const {
  if (!position.allFinite()) return false;
  if (*hint < 0 || *hint >= num_nodes()) *hint = LocateNode(position);
  // Walk to the nearest site over links, keeping the last squared distances
  // for the blend below (the nearest node and its links).
  thread_local std::vector<double> d2;
  int node = *hint;
  for (int step = 0; step < 64; ++step) {
    const int* begin = links_begin(node);
    const int count = static_cast<int>(links_end(node) - begin);
    d2.resize(static_cast<size_t>(count) + 1);
    d2[0] = (position - sites_[static_cast<size_t>(node)]).squaredNorm();
    int best = node;
    double best_d2 = d2[0];
    for (int i = 0; i < count; ++i) {
      d2[static_cast<size_t>(i) + 1] =
          (position - sites_[static_cast<size_t>(begin[i])]).squaredNorm();
      if (d2[static_cast<size_t>(i) + 1] < best_d2)
        best_d2 = d2[static_cast<size_t>(i) + 1], best = begin[i];
    }
    if (best == node) break;
    node = best;
  }
  *hint = node;
  *plane = surfaces_[static_cast<size_t>(node)].PlaneAt(position);
  if (blend_ <= 0) return true;
  // Partition of unity over the nearest node and its linked neighbours.
  const Eigen::Vector3d reference = plane->normal;
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  double total = 0;
  const double inverse = 1.0 / (blend_ * blend_);
  const int* links = links_begin(node);
  for (size_t i = 0; i < d2.size(); ++i) {
    const double t2 = d2[i] * inverse;
    if (t2 >= 1) continue;
    const double w = (1 - t2) * (1 - t2);
    const TangentPlane p =
        i == 0 ? *plane : surfaces_[static_cast<size_t>(links[i - 1])].PlaneAt(position);
    point += w * p.point;
    normal += (p.normal.dot(reference) < 0 ? -w : w) * p.normal;
    total += w;
  }
  if (total > 0 && normal.norm() > 0) {
    plane->point = point / total;
    plane->normal = normal.normalized();
  }
  return true;
}

std::int64_t CloudGrid::memory_bytes() const {
  const auto n = static_cast<std::int64_t>(sites_.size());
  return n * static_cast<std::int64_t>(sizeof(Eigen::Vector3d) + sizeof(LocalSurface) + 8 + 4) +
         static_cast<std::int64_t>(node_normal_.size() * sizeof(Eigen::Vector3d)) +
         static_cast<std::int64_t>(cells_.size()) * 40 +
         static_cast<std::int64_t>(link_targets_.size() + link_offsets_.size() +
                                   node_points_.size() + point_node_.size()) *
             4 +
         index_->size() * 3 * 8 * 2;
}

}  // namespace bespoke
