#include "measure/cloud_geodesic/propagation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "measure/mesh_geodesic/window_chain.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {

namespace {}  // namespace

Propagation::Propagation(const PropagationOptions& options, const CloudGrid& grid,
                         const Eigen::Vector3d& source, int source_node, PropagationPool recycled)
    : options_(options),
      grid_(grid),
      source_(source),
      source_node_(source_node),
      pool_(std::move(recycled)),
      wavefront_(grid.num_nodes(), options.band_spacings * grid.cell_size_mm()) {
  Init();
  // The source node's path: the source itself, then its site.
  const Eigen::Vector3d& site = grid.site(source_node);
  const bool apart = (site - source).norm() > 1e-6 * grid.cell_size_mm();
  Eigen::MatrixX3d window(apart ? 2 : 1, 3);
  window.row(0) = source.transpose();
  if (apart) window.row(1) = site.transpose();
  std::vector<int> hints(static_cast<size_t>(window.rows()), source_node);
  std::vector<TangentPlane> planes;
  parent_[source_node] = -1;
  FillMissingPlanes(grid, window, &hints, &planes);
  distance_[source_node] = SurfaceCurveLength(window, planes);
  if (apart) {
    const Eigen::Vector3d normal = grid.surface(source_node).PlaneAt(site).normal;
    Eigen::Vector3d t = site - source;
    t -= normal * normal.dot(t);
    if (t.norm() > 0) tangent_[source_node] = t.normalized();
  }
  Store(source_node, window, hints, planes);
  stats_.settled = 1;
  wavefront_.Seed(source_node);
  wavefront_.set_r_max(distance_[source_node] + options_.band_spacings * grid.cell_size_mm());
}

void Propagation::Init() {
  options_.Check();
  flow_ = FlowOptionsFor(options_, grid_.cell_size_mm());
  const int n = grid_.num_nodes();
  if (source_node_ < 0 || source_node_ >= n)
    throw InputError("propagation: source node " + std::to_string(source_node_) + " out of range");
  if (!source_.allFinite()) throw InputError("propagation: the source is not finite");
  distance_.assign(static_cast<size_t>(n), kInf);
  prefix_.assign(static_cast<size_t>(n), 0.0);
  parent_.assign(static_cast<size_t>(n), -1);
  start_.assign(static_cast<size_t>(n), 0);
  count_.assign(static_cast<size_t>(n), 0);
  offset_.assign(static_cast<size_t>(n), 0);
  tangent_.assign(static_cast<size_t>(n), Eigen::Vector3d::Zero());
  pool_.points.clear();
  pool_.hints.clear();
  pool_.planes.clear();
}

Propagation::Propagation(const PropagationOptions& options, const CloudGrid& grid,
                         const Eigen::Vector3d& source, const std::vector<int>& seeds,
                         PropagationPool recycled)
    : options_(options),
      grid_(grid),
      source_(source),
      source_node_(seeds.empty() ? -1 : seeds.front()),
      pool_(std::move(recycled)),
      wavefront_(grid.num_nodes(), options.band_spacings * grid.cell_size_mm()) {
  if (seeds.empty()) throw InputError("propagation: no seed nodes round the source");
  Init();
  double nearest = kInf;
  for (const int seed : seeds) {
    if (seed < 0 || seed >= grid.num_nodes())
      throw InputError("propagation: seed node " + std::to_string(seed) + " out of range");
    if (settled(seed)) continue;
    const Eigen::Vector3d& site = grid.site(seed);
    Eigen::MatrixX3d window(2, 3);
    window.row(0) = source.transpose();
    window.row(1) = site.transpose();
    const std::vector<int> hints = {seed, seed};
    std::vector<TangentPlane> planes(2);  // zero normals: the chord counts as a chord
    planes[0].point = source;
    planes[1] = grid.surface(seed).PlaneAt(site);
    distance_[seed] = (site - source).norm();
    const Eigen::Vector3d normal = planes[1].normal;
    Eigen::Vector3d t = site - source;
    t -= normal * normal.dot(t);
    if (t.norm() > 0) tangent_[seed] = t.normalized();
    Store(seed, window, hints, planes);
    ++stats_.settled;
    wavefront_.Seed(seed);
    nearest = std::min(nearest, distance_[seed]);
  }
  wavefront_.set_r_max(nearest + options_.band_spacings * grid.cell_size_mm());
}

void Propagation::Store(int node, const Eigen::MatrixX3d& window, const std::vector<int>& hints,
                        const std::vector<TangentPlane>& planes) {
  offset_[node] = static_cast<std::int64_t>(pool_.points.size());
  count_[node] = static_cast<int>(window.rows());
  for (Eigen::Index i = 0; i < window.rows(); ++i) {
    pool_.points.push_back(window.row(i).transpose());
    pool_.hints.push_back(hints[static_cast<size_t>(i)]);
    pool_.planes.push_back(planes[static_cast<size_t>(i)]);
  }
}

ParentChoice Propagation::ChooseParent(int node) const {
  return bespoke::ChooseParent(*this, node, options_.parent_rule,
                               options_.tie_spacings * grid_.cell_size_mm());
}

void Propagation::Settle(int node, int parent) {
  const int k = count_[parent];
  Eigen::MatrixX3d path(k + 1, 3);
  std::vector<int> hints(static_cast<size_t>(k + 1));
  std::vector<TangentPlane> planes(static_cast<size_t>(k + 1));
  for (int i = 0; i < k; ++i) {
    const size_t at = static_cast<size_t>(offset_[parent] + i);
    path.row(i) = pool_.points[at].transpose();
    hints[i] = pool_.hints[at];
    planes[i] = pool_.planes[at];
  }
  path.row(k) = grid_.site(node).transpose();
  hints[k] = node;
  planes[k].normal.setZero();
  const int drop = options_.whole_path ? 0 : std::max(0, k + 1 - options_.window);
  double prefix = prefix_[parent];
  if (drop > 0) {
    std::vector<int> h(hints.begin(), hints.begin() + drop + 1);
    std::vector<TangentPlane> p(planes.begin(), planes.begin() + drop + 1);
    const Eigen::MatrixX3d dropped = path.topRows(drop + 1);
    FillMissingPlanes(grid_, dropped, &h, &p);
    prefix += SurfaceCurveLength(dropped, p);
  }
  Eigen::MatrixX3d window = path.bottomRows(k + 1 - drop);
  hints.erase(hints.begin(), hints.begin() + drop);
  planes.erase(planes.begin(), planes.begin() + drop);
  if (window.rows() >= 3) {
    const Eigen::MatrixX3d inherited = window;
    const std::vector<int> inherited_hints = hints;
    const std::vector<TangentPlane> inherited_planes = planes;
    const CurvatureFlowReport report = FlowPolyline(flow_, grid_, &window, &hints, &planes);
    ++stats_.flows;
    stats_.flow_iterations += report.iterations;
    if (!report.converged) ++stats_.unconverged;
    bool on_surface = true;
    for (size_t i = 1; i < hints.size() && on_surface; ++i)
      on_surface = grid_.StepOnSurface(hints[i - 1], window.row(i - 1).transpose(), hints[i],
                                       window.row(i).transpose());
    if (!on_surface) {
      ++stats_.undone;
      window = inherited;
      hints = inherited_hints;
      planes = inherited_planes;
    }
  }
  parent_[node] = parent;
  start_[node] = start_[parent] + drop;
  prefix_[node] = prefix;
  FillMissingPlanes(grid_, window, &hints, &planes);
  distance_[node] = prefix + SurfaceCurveLength(window, planes);
  const Eigen::Index m = window.rows();
  Eigen::Vector3d t = (window.row(m - 1) - window.row(m - 2)).transpose();
  const Eigen::Vector3d normal = grid_.surface(node).PlaneAt(grid_.site(node)).normal;
  t -= normal * normal.dot(t);
  tangent_[node] = t.norm() > 0 ? t.normalized() : Eigen::Vector3d::Zero();
  Store(node, window, hints, planes);
  ++stats_.settled;
}

void Propagation::Run(int target, Progress* progress) {
  if (target >= grid_.num_nodes()) throw InputError("propagation: target node out of range");
  wavefront_.Run(*this, target, "propagating geodesics", 1024, progress);
  stats_.rounds = wavefront_.rounds();
}

Eigen::MatrixX3d Propagation::Path(int node, std::vector<int>* hints) const {
  if (node < 0 || node >= grid_.num_nodes() || !settled(node))
    throw InputError("propagation: no path to node " + std::to_string(node));
  const auto chain =
      WindowChain(node, parent_, start_, [&](int u) { return count_[static_cast<size_t>(u)]; });
  return ChainPolyline(
      chain,
      [&](int u, int i) {
        const size_t at = static_cast<size_t>(offset_[static_cast<size_t>(u)] + i);
        return std::pair<const Eigen::Vector3d&, int>(pool_.points[at], pool_.hints[at]);
      },
      hints);
}

double Propagation::DistanceNear(int node, const Eigen::Vector3d& x) const {
  if (!settled(node)) return kInf;
  const Eigen::Vector3d n = grid_.surface(node).normal();
  Eigen::Vector3d e = x - grid_.site(node);
  e -= n * n.dot(e);
  const Eigen::Vector3d& t = tangent_[node];
  if (t.squaredNorm() == 0) return distance_[node] + e.norm();
  const double along = t.dot(e);
  return std::hypot(distance_[node] + along, (e - along * t).norm());
}

std::int64_t Propagation::memory_bytes() const {
  const auto n = static_cast<std::int64_t>(distance_.size());
  return n * (8 * 2 + 4 * 4 + 8 + 24) + static_cast<std::int64_t>(pool_.points.capacity()) * 24 +
         static_cast<std::int64_t>(pool_.hints.capacity()) * 4 +
         static_cast<std::int64_t>(pool_.planes.capacity()) *
             static_cast<std::int64_t>(sizeof(TangentPlane));
}

}  // namespace bespoke
