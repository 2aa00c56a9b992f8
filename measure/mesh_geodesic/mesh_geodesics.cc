#include "measure/mesh_geodesic/mesh_geodesics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "measure/mesh_geodesic/path_projection.h"
#include "measure/mesh_geodesic/window_chain.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {

namespace {
// True when every pair of consecutive samples has nearest vertices at most
// three edges apart in the mesh graph: the flowed path does not jump between
// parts of the surface that are close in space but apart over the surface
// (lips, eyelids, fingers), where the two vertices are many edges apart.
bool OnSurface(const MeshSurface& surface, const Eigen::MatrixX3d& path, std::vector<int>* hints) {
  auto& h = *hints;
  std::vector<int> ring;
  surface.NearestVertex(path.row(0).transpose(), &h[0]);  // the flow's hints may be stale
  for (size_t i = 1; i < h.size(); ++i) {
    surface.NearestVertex(path.row(static_cast<Eigen::Index>(i)).transpose(), &h[i]);
    if (h[i] == h[i - 1] ||
        std::find(surface.neighbours_begin(h[i - 1]), surface.neighbours_end(h[i - 1]), h[i]) !=
            surface.neighbours_end(h[i - 1]))
      continue;
    ring.assign(1, h[i - 1]);
    bool near = false;
    for (size_t begin = 0, depth = 0; depth < 3 && !near; ++depth) {
      const size_t end = ring.size();
      for (size_t k = begin; k < end && !near; ++k)
        for (const int* u = surface.neighbours_begin(ring[k]); u != surface.neighbours_end(ring[k]);
             ++u) {
          if (*u == h[i]) {
            near = true;
            break;
          }
          if (std::find(ring.begin(), ring.end(), *u) == ring.end()) ring.push_back(*u);
        }
      begin = end;
    }
    if (!near) return false;
  }
  return true;
}

}  // namespace

void MeshGeodesicsOptions::Check() const { wavefront.Check(); }

MeshGeodesics::MeshGeodesics(const MeshGeodesicsOptions& options, const MeshSurface& surface,
                             int source)
    : options_(options),
      surface_(surface),
      source_(source),
      wavefront_(surface.num_vertices(),
                 options.wavefront.band_spacings * surface.mean_edge_length()) {
  options_.Check();
  const int n = surface.num_vertices();
  if (source < 0 || source >= n)
    throw InputError(surface.name(), "source vertex " + std::to_string(source) +
                                         " is out of range (the mesh has " + std::to_string(n) +
                                         " vertices)");
  if (!surface.used(source))
    throw InputError(surface.name(),
                     "source vertex " + std::to_string(source) + " is used by no face");
  const double edge = surface.mean_edge_length();
  flow_ = FlowOptionsFor(options_.wavefront, edge);
  const auto size = static_cast<size_t>(n);
  offset_.assign(size, kInf);
  projected_.assign(size, kInf);
  bound_.assign(size, kInf);
  parent_.assign(size, -1);
  start_.assign(size, 0);
  settled_.assign(size, 0);
  tangent_.assign(size, Eigen::Vector3d::Zero());
  windows_.resize(size);
  open_.resize(size);
  for (int v = 0; v < n; ++v)
    open_[static_cast<size_t>(v)] =
        static_cast<int>(surface.neighbours_end(v) - surface.neighbours_begin(v));
  Sample s;
  s.point = surface.position(source);
  s.hint = source;
  int hint = source;
  if (!surface.PlaneAt(s.point, &hint, &s.plane)) s.plane.normal.setZero();
  windows_[size_t(source)].push_back(s);
  live_samples_ = 1;
  offset_[size_t(source)] = projected_[size_t(source)] = bound_[size_t(source)] = 0;
  settled_[size_t(source)] = 1;
  for (const int* u = surface.neighbours_begin(source); u != surface.neighbours_end(source); ++u)
    --open_[static_cast<size_t>(*u)];
  stats_.settled = 1;
  wavefront_.Seed(source);
  wavefront_.set_r_max(options_.wavefront.band_spacings * edge);
}

ParentChoice MeshGeodesics::ChooseParent(int v) const {
  return bespoke::ChooseParent(*this, v, options_.wavefront.parent_rule,
                               options_.wavefront.tie_spacings * surface_.mean_edge_length());
}

void MeshGeodesics::Release(int v) {
  if (options_.keep_paths) return;
  auto& w = windows_[static_cast<size_t>(v)];
  live_samples_ -= static_cast<std::int64_t>(w.size());
  std::vector<Sample>().swap(w);
}

void MeshGeodesics::Settle(int v, int parent) {
  const std::vector<Sample>& pw = windows_[static_cast<size_t>(parent)];
  const int k = static_cast<int>(pw.size());
  const int drop =
      options_.wavefront.whole_path ? 0 : std::max(0, k + 1 - options_.wavefront.window);
  const int m = k + 1 - drop;
  path_.resize(m, 3);
  hints_.resize(static_cast<size_t>(m));
  planes_.resize(static_cast<size_t>(m));
  for (int i = 0; i < m - 1; ++i) {
    const Sample& s = pw[static_cast<size_t>(drop + i)];
    path_.row(i) = s.point.transpose();
    hints_[size_t(i)] = s.hint;
    planes_[size_t(i)] = s.plane;
  }
  path_.row(m - 1) = surface_.position(v).transpose();
  hints_[size_t(m - 1)] = v;
  planes_[size_t(m - 1)].normal.setZero();
  // Flow the window; when the flow leaves the surface or cuts across a gap
  // between parts of it (lips, eyelids, fingers), flow only the last half,
  // quarter, ... of it; if even 3 samples fail, keep the inherited path.
  for (int tail = m; tail >= 3; tail = tail > 3 ? std::max(3, tail / 2) : 0) {
    Eigen::MatrixX3d part = path_.bottomRows(tail);
    std::vector<int> part_hints(hints_.end() - tail, hints_.end());
    std::vector<TangentPlane> part_planes(planes_.end() - tail, planes_.end());
    const CurvatureFlowReport report =
        FlowPolyline(flow_, surface_, &part, &part_hints, &part_planes);
    ++stats_.flows;
    stats_.flow_iterations += report.iterations;
    if (!report.converged) ++stats_.unconverged;
    if (report.samples_without_plane == 0 && OnSurface(surface_, part, &part_hints)) {
      path_.bottomRows(tail) = part;
      std::copy(part_hints.begin(), part_hints.end(), hints_.end() - tail);
      std::copy(part_planes.begin(), part_planes.end(), planes_.end() - tail);
      break;
    }
    ++stats_.undone;
  }
  FillMissingPlanes(surface_, path_, &hints_, &planes_);
  std::vector<Sample> window(static_cast<size_t>(m));
  const Sample& first = pw[static_cast<size_t>(drop)];
  double arc = first.arc;
  for (int i = 0; i < m; ++i) {
    Sample& s = window[size_t(i)];
    s.point = path_.row(i).transpose();
    s.hint = hints_[size_t(i)];
    s.plane = planes_[size_t(i)];
    if (i > 0) arc += (path_.row(i) - path_.row(i - 1)).norm();
    s.arc = arc;
  }
  window[0].projected = first.projected;
  if (options_.project) {
    std::vector<int> hints = hints_;
    const Eigen::Vector3d* before = drop > 0 ? &pw[static_cast<size_t>(drop - 1)].point : nullptr;
    const ProjectedPath proj = ProjectPolyline(surface_, path_, &hints, before, false);
    stats_.projection_fallbacks += proj.fallbacks;
    for (int i = 1; i < m; ++i)
      window[size_t(i)].projected = first.projected + proj.cumulative[size_t(i)];
  }
  // Eq 3.20-3.24: the kink left at the held first sample of the window.
  double bound = bound_[size_t(parent)];
  if (drop > 0 && m >= 2) {
    const Eigen::Vector3d& n = first.plane.normal;
    Eigen::Vector3d in = first.point - pw[static_cast<size_t>(drop - 1)].point;
    Eigen::Vector3d out = window[1].point - first.point;
    if (n.squaredNorm() > 0) {
      in -= n.dot(in) / n.squaredNorm() * n;
      out -= n.dot(out) / n.squaredNorm() * n;
    }
    const double length = window.back().arc - first.arc;
    const double sine =
        in.norm() > 0 && out.norm() > 0 ? in.cross(out).norm() / (in.norm() * out.norm()) : 0;
    const double y_max = 0.5 * length * sine;
    bound += std::sqrt(length * length + 4 * y_max * y_max) - length;
  }
  const size_t at = static_cast<size_t>(v);
  parent_[at] = parent;
  start_[at] = start_[size_t(parent)] + drop;
  offset_[at] = window.back().arc;
  projected_[at] = options_.project ? window.back().projected : kInf;
  bound_[at] = options_.wavefront.whole_path ? 0 : bound;
  Eigen::Vector3d t = (path_.row(m - 1) - path_.row(m - 2)).transpose();
  const Eigen::Vector3d& normal = surface_.normal(v);
  t -= normal * normal.dot(t);
  tangent_[at] = t.norm() > 0 ? t.normalized() : Eigen::Vector3d::Zero();
  live_samples_ += m;
  stats_.peak_window_samples = std::max(stats_.peak_window_samples, live_samples_);
  windows_[at] = std::move(window);
  settled_[at] = 1;
  ++stats_.settled;
  for (const int* u = surface_.neighbours_begin(v); u != surface_.neighbours_end(v); ++u)
    if (--open_[static_cast<size_t>(*u)] == 0 && settled(*u)) Release(*u);
  if (open_[at] == 0) Release(v);
}

void MeshGeodesics::Run(int target, Progress* progress) {
  if (target >= surface_.num_vertices())
    throw InputError("mesh geodesics: target vertex out of range");
  wavefront_.Run(*this, target, "propagating mesh geodesics", 4096, progress);
  stats_.rounds = wavefront_.rounds();
}

Eigen::MatrixX3d MeshGeodesics::Path(int v, std::vector<int>* hints) const {
  if (v < 0 || v >= surface_.num_vertices() || !settled(v))
    throw InputError("mesh geodesics: no path to vertex " + std::to_string(v));
  if (!options_.keep_paths) throw InputError("mesh geodesics: paths were not kept (keep_paths)");
  const auto chain = WindowChain(
      v, parent_, start_, [&](int u) { return static_cast<int>(windows_[size_t(u)].size()); });
  return ChainPolyline(
      chain,
      [&](int u, int i) {
        const Sample& s = windows_[size_t(u)][size_t(i)];
        return std::pair<const Eigen::Vector3d&, int>(s.point, s.hint);
      },
      hints);
}

}  // namespace bespoke
