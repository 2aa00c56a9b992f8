#include "measure/cloud_geodesic/propagation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

void PropagationOptions::Check() const {
  if (window < 3)
    throw InputError("propagation: window must be >= 3, got " + std::to_string(window));
  if (!(band_cells >= 0) || !std::isfinite(band_cells))
    throw InputError("propagation: band_cells must be >= 0");
  if (!(tie_cells >= 0) || !std::isfinite(tie_cells))
    throw InputError("propagation: tie_cells must be >= 0");
  if (flow_iterations < 1) throw InputError("propagation: flow_iterations must be >= 1");
  if (!(flow_tolerance_cells > 0) || !std::isfinite(flow_tolerance_cells))
    throw InputError("propagation: flow_tolerance_cells must be > 0");
  if (!(replan_cells >= 0) || !std::isfinite(replan_cells))
    throw InputError("propagation: replan_cells must be >= 0");
  if (!(max_step_segments > 0) || !std::isfinite(max_step_segments))
    throw InputError("propagation: max_step_segments must be > 0");
}

Propagation::Propagation(const PropagationOptions& options, const CloudGrid& grid,
                         const Eigen::Vector3d& source, int source_node)
    : options_(options), grid_(grid), source_(source), source_node_(source_node) {
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
  front_.push_back(source_node);
  r_max_ = distance_[source_node] + options_.band_cells * grid.cell_size_mm();
  min_held_ = kInf;
  max_held_ = 0;
}

void Propagation::Init() {
  options_.Check();
  flow_.max_iterations = options_.flow_iterations;
  flow_.tolerance_mm = options_.flow_tolerance_cells * grid_.cell_size_mm();
  flow_.replan_distance_mm = options_.replan_cells * grid_.cell_size_mm();
  flow_.max_step_segments = options_.max_step_segments;
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
  stamp_.assign(static_cast<size_t>(n), -1);
}

Propagation::Propagation(const PropagationOptions& options, const CloudGrid& grid,
                         const Eigen::Vector3d& source, const std::vector<int>& seeds)
    : options_(options),
      grid_(grid),
      source_(source),
      source_node_(seeds.empty() ? -1 : seeds.front()) {
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
    front_.push_back(seed);
    nearest = std::min(nearest, distance_[seed]);
  }
  r_max_ = nearest + options_.band_cells * grid.cell_size_mm();
  min_held_ = kInf;
  max_held_ = 0;
}

void Propagation::Store(int node, const Eigen::MatrixX3d& window, const std::vector<int>& hints,
                        const std::vector<TangentPlane>& planes) {
  offset_[node] = static_cast<std::int64_t>(pool_.size());
  count_[node] = static_cast<int>(window.rows());
  for (Eigen::Index i = 0; i < window.rows(); ++i) {
    pool_.push_back(window.row(i).transpose());
    pool_hints_.push_back(hints[static_cast<size_t>(i)]);
    pool_planes_.push_back(planes[static_cast<size_t>(i)]);
  }
}

Propagation::Choice Propagation::ChooseParent(int node) const {
  const Eigen::Vector3d& site = grid_.site(node);
  struct Candidate {
    int node;
    double predicted, cosine, simple;
  };
  Candidate found[64];
  int count = 0;
  double best = kInf;
  for (const int* l = grid_.links_begin(node); l != grid_.links_end(node) && count < 64; ++l) {
    const int v = *l;
    if (!settled(v)) continue;
    const Eigen::Vector3d e = site - grid_.site(v);
    const double length = e.norm();
    const Eigen::Vector3d& t = tangent_[v];
    Candidate c{v, distance_[v] + length, 1.0, distance_[v] + length};
    if (t.squaredNorm() > 0 && length > 0) {
      const double along = t.dot(e);
      const Eigen::Vector3d n = grid_.surface(v).normal();
      Eigen::Vector3d lateral = e - along * t;
      lateral -= n * n.dot(lateral);
      // Distance from a virtual source distance_[v] behind v along t,
      // developed into v's tangent plane (exact on a plane).
      c.predicted = std::hypot(distance_[v] + along, lateral.norm());
      c.cosine = along / length;
    }
    best = std::min(best, c.predicted);
    found[count++] = c;
  }
  Choice choice;
  double best_cosine = -kInf;
  const double tie = options_.tie_cells * grid_.cell_size_mm();
  for (int i = 0; i < count; ++i) {
    const Candidate& c = found[i];
    if (options_.parent_rule == ParentRule::kPredicted && c.predicted > best + tie) continue;
    if (c.cosine > best_cosine) {
      best_cosine = c.cosine;
      choice.parent = c.node;
      choice.estimate = options_.parent_rule == ParentRule::kPredicted ? c.predicted : c.simple;
    }
  }
  return choice;
}

void Propagation::Settle(int node, int parent) {
  const int k = count_[parent];
  Eigen::MatrixX3d path(k + 1, 3);
  std::vector<int> hints(static_cast<size_t>(k + 1));
  std::vector<TangentPlane> planes(static_cast<size_t>(k + 1));
  for (int i = 0; i < k; ++i) {
    const size_t at = static_cast<size_t>(offset_[parent] + i);
    path.row(i) = pool_[at].transpose();
    hints[i] = pool_hints_[at];
    planes[i] = pool_planes_[at];
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
      ++stats_.rejected;
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
  if (done_ || (target >= 0 && settled(target))) return;
  const double band = options_.band_cells * grid_.cell_size_mm();
  ProgressBegin(progress, "propagating geodesics", grid_.num_nodes());
  std::int64_t reported = stats_.settled;
  std::vector<int> wave;
  while (!(target >= 0 && settled(target))) {
    if (front_.empty()) {  // W and W' are exhausted: widen r_max, expand W_next
      if (next_.empty()) {
        done_ = true;
        break;
      }
      front_.swap(next_);
      next_.clear();
      ++stats_.rounds;
      r_max_ = band > 0 ? std::max(r_max_, min_held_) + band : std::max(r_max_, max_held_);
      min_held_ = kInf;
      max_held_ = 0;
    }
    wave.clear();
    wave.swap(front_);  // W; settled nodes go to W' (front_)
    for (const int c : wave) {
      bool held = false;
      for (const int* l = grid_.links_begin(c); l != grid_.links_end(c); ++l) {
        if (settled(*l)) continue;
        const Choice choice = ChooseParent(*l);
        if (choice.estimate <= r_max_) {
          Settle(*l, choice.parent);
          front_.push_back(*l);
        } else {
          held = true;
          min_held_ = std::min(min_held_, choice.estimate);
          max_held_ = std::max(max_held_, choice.estimate);
        }
      }
      if (held && stamp_[c] != stats_.rounds) {
        stamp_[c] = static_cast<int>(stats_.rounds);
        next_.push_back(c);
      }
    }
    if (stats_.settled - reported >= 1024) {
      reported = stats_.settled;
      ProgressUpdate(progress, stats_.settled);
    }
  }
  ProgressEnd(progress);
}

Eigen::MatrixX3d Propagation::Path(int node, std::vector<int>* hints) const {
  if (node < 0 || node >= grid_.num_nodes() || !settled(node))
    throw InputError("propagation: no path to node " + std::to_string(node));
  std::vector<std::pair<int, int>> chunks;  // (node, samples from its window start)
  chunks.emplace_back(node, count_[node]);
  int need = start_[node];
  for (int cur = parent_[node]; need > 0; cur = parent_[cur]) {
    BESPOKE_CHECK(cur >= 0, "broken parent chain");
    const int take = need - start_[cur];
    BESPOKE_CHECK(take >= 0 && take <= count_[cur], "inconsistent window chain");
    chunks.emplace_back(cur, take);
    need = start_[cur];
  }
  Eigen::Index total = 0;
  for (const auto& [n, take] : chunks) total += take;
  Eigen::MatrixX3d out(total, 3);
  if (hints) hints->resize(static_cast<size_t>(total));
  Eigen::Index row = 0;
  for (auto it = chunks.rbegin(); it != chunks.rend(); ++it)
    for (int i = 0; i < it->second; ++i, ++row) {
      const size_t at = static_cast<size_t>(offset_[it->first] + i);
      out.row(row) = pool_[at].transpose();
      if (hints) (*hints)[static_cast<size_t>(row)] = pool_hints_[at];
    }
  return out;
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
  return n * (8 * 2 + 4 * 4 + 8 + 24) + static_cast<std::int64_t>(pool_.capacity()) * 24 +
         static_cast<std::int64_t>(pool_hints_.capacity()) * 4 +
         static_cast<std::int64_t>(pool_planes_.capacity()) *
             static_cast<std::int64_t>(sizeof(TangentPlane));
}

}  // namespace bespoke
