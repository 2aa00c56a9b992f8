#include "measure/cloud_geodesic/cloud_geodesics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "scanners/core/errors.h"

namespace bespoke {

void CloudGeodesicsOptions::Check() const {
  grid.Check();
  propagation.Check();
  polish_flow.Check();
  point_field.Check();
  if (!(max_snap_distance_mm >= 0) || !std::isfinite(max_snap_distance_mm))
    throw InputError("geodesics: max_snap_distance_mm must be >= 0");
  if (!(max_hole_snap_distance_mm >= 0) || !std::isfinite(max_hole_snap_distance_mm))
    throw InputError("geodesics: max_hole_snap_distance_mm must be >= 0");
  if (!(polish_spacing_mm >= 0) || !std::isfinite(polish_spacing_mm))
    throw InputError("geodesics: polish_spacing_mm must be >= 0");
  if (polish_splits < 0 || polish_splits > 8)
    throw InputError("geodesics: polish_splits must be 0-8");
}

namespace {

const CloudGeodesicsOptions& Checked(const CloudGeodesicsOptions& options) {
  options.Check();
  return options;
}

// The first sample i of `samples` (#S x 3, mm) whose step from sample i - 1
// leaves the surface (CloudGrid::StepOnSurface), or -1.
Eigen::Index FirstStepOff(const CloudGrid& grid, const Eigen::MatrixX3d& samples,
                          const std::vector<int>& hints) {
  for (Eigen::Index i = 1; i < samples.rows(); ++i)
    if (!grid.StepOnSurface(hints[static_cast<size_t>(i - 1)], samples.row(i - 1).transpose(),
                            hints[static_cast<size_t>(i)], samples.row(i).transpose()))
      return i;
  return -1;
}

// A path piece, its samples' grid hints and tangent planes.
struct Piece {
  Eigen::MatrixX3d samples;
  std::vector<int> hints;
  std::vector<TangentPlane> planes;
  Piece Rows(Eigen::Index first, Eigen::Index last) const {
    const auto n = static_cast<std::ptrdiff_t>(last - first + 1);
    const auto at = static_cast<std::ptrdiff_t>(first);
    return {samples.middleRows(first, last - first + 1),
            std::vector<int>(hints.begin() + at, hints.begin() + at + n),
            std::vector<TangentPlane>(planes.begin() + at, planes.begin() + at + n)};
  }
  // `head` then `tail` without its first sample (the one they share).
  static Piece Joined(const Piece& head, const Piece& tail) {
    Piece out;
    out.samples.resize(head.samples.rows() + tail.samples.rows() - 1, 3);
    out.samples << head.samples, tail.samples.bottomRows(tail.samples.rows() - 1);
    out.hints = head.hints;
    out.hints.insert(out.hints.end(), tail.hints.begin() + 1, tail.hints.end());
    out.planes = head.planes;
    out.planes.insert(out.planes.end(), tail.planes.begin() + 1, tail.planes.end());
    return out;
  }
};

// Flows `piece` (its end samples held) into a locally shortest path on the
// surface. A flow that cuts across a gap - a step between two sheets, or off
// a hole's rim into the air, as round an armpit or between touching thighs
// - is undone; the piece is then split at the sample of that step, held where
// the propagation put it (on links of the grid), and each half is flowed on
// its own, at most `depth` splits deep. A part still off the surface keeps
// its propagated samples. Returns false when some part kept them.
bool PolishPiece(const CurvatureFlowOptions& flow, const CloudGrid& grid, int depth, Piece* piece,
                 CurvatureFlowReport* report) {
  Piece flowed = *piece;
  const CurvatureFlowReport r =
      FlowPolyline(flow, grid, &flowed.samples, &flowed.hints, &flowed.planes);
  report->iterations = std::max(report->iterations, r.iterations);
  const Eigen::Index off = FirstStepOff(grid, flowed.samples, flowed.hints);
  if (off < 0) {
    report->converged = report->converged && r.converged;
    *piece = std::move(flowed);
    return true;
  }
  const Eigen::Index rows = piece->samples.rows();
  if (depth == 0 || rows < 5) return false;
  const Eigen::Index split = std::clamp<Eigen::Index>(off, 2, rows - 3);
  Piece head = piece->Rows(0, split), tail = piece->Rows(split, rows - 1);
  const bool ok_head = PolishPiece(flow, grid, depth - 1, &head, report);
  const bool ok_tail = PolishPiece(flow, grid, depth - 1, &tail, report);
  *piece = Piece::Joined(head, tail);
  return ok_head && ok_tail;
}

}  // namespace

CloudGeodesics::CloudGeodesics(const CloudGeodesicsOptions& options, const Eigen::MatrixX3d& points,
                               Progress* progress)
    : options_(Checked(options)),
      shared_grid_(std::make_shared<const CloudGrid>(options.grid, points, progress)),
      grid_(*shared_grid_) {}

CloudGeodesics::CloudGeodesics(const CloudGeodesicsOptions& options, const Eigen::MatrixX3d& points,
                               const Eigen::MatrixX3d& normals, Progress* progress)
    : options_(Checked(options)),
      shared_grid_(std::make_shared<const CloudGrid>(options.grid, points, normals, progress)),
      grid_(*shared_grid_) {}

CloudGeodesics::CloudGeodesics(const CloudGeodesicsOptions& options,
                               std::shared_ptr<const CloudGrid> grid)
    : options_(Checked(options)), shared_grid_(std::move(grid)), grid_(*shared_grid_) {}

std::unique_ptr<CloudGeodesics> CloudGeodesics::Fork() const {
  return std::unique_ptr<CloudGeodesics>(new CloudGeodesics(options_, shared_grid_));
}

CloudGeodesics::~CloudGeodesics() = default;

std::string CloudGeodesics::FormatPoint(const Eigen::Vector3d& x) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f)", x.x(), x.y(), x.z());
  return text;
}

std::pair<Eigen::Vector3d, int> CloudGeodesics::Snap(const Eigen::Vector3d& x,
                                                     const std::string& what, int component,
                                                     double* snap_mm, bool* unscanned) const {
  if (!x.allFinite()) throw InputError(what + ": coordinates must be finite numbers");
  const double limit = options_.max_snap_distance_mm > 0 ? options_.max_snap_distance_mm
                                                         : std::max(10.0, 3 * grid_.cell_size_mm());
  const double hole_limit = std::max(limit, options_.max_hole_snap_distance_mm);
  double distance = 0;
  int node = grid_.LocateNode(x, &distance, component);
  if (component >= 0 && grid_.component(node) == component) {
    // A nearer point on another sizeable piece: x lies on that piece, not
    // on `component` (a target across a gap the grid does not link must
    // not snap back onto the source's piece; small islands are skipped).
    double nearest_distance = 0;
    const int nearest = grid_.LocateNode(x, &nearest_distance);
    const auto& sizes = grid_.component_points();
    if (grid_.component(nearest) != component && nearest_distance < distance &&
        sizes[static_cast<size_t>(grid_.component(nearest))] >= 0.05 * sizes[0]) {
      node = nearest;
      distance = nearest_distance;
    }
  }
  if (component < 0) {
    const auto& sizes = grid_.component_points();
    if (sizes[static_cast<size_t>(grid_.component(node))] < 0.05 * sizes[0]) {
      double main_distance = 0;
      const int main = grid_.LocateNode(x, &main_distance, 0);
      if (grid_.component(main) == 0 && main_distance <= hole_limit) {
        node = main;
        distance = main_distance;
      }
    }
  }
  const bool hole =
      distance > limit && distance <= hole_limit && InUnscannedRegion(x, distance, node);
  if (distance > limit && !hole) {
    char text[240];
    std::snprintf(text, sizeof text,
                  " is %.1f mm from the nearest scan point (at most %.1f mm allowed, or %.1f mm "
                  "inside an unscanned region the scan surrounds); give coordinates on the "
                  "surface, in the scan's frame and units (mm)",
                  distance, limit, hole_limit);
    throw InputError(what + " " + FormatPoint(x) + text);
  }
  const Eigen::Vector3d point = grid_.surface(node).PlaneAt(hole ? grid_.site(node) : x).point;
  if (snap_mm) *snap_mm = (point - x).norm();
  if (unscanned) *unscanned = hole;
  return {point, node};
}

PropagationPool CloudGeodesics::TakeCachedPool() {
  if (!cached_) return {};
  PropagationPool pool = cached_->TakePool();
  cached_.reset();
  return pool;
}

Propagation& CloudGeodesics::PropagationFrom(const Eigen::Vector3d& source, int node) {
  if (!cached_ || cached_->source_node() != node || cached_->source() != source)
    cached_ =
        std::make_unique<Propagation>(options_.propagation, grid_, source, node, TakeCachedPool());
  return *cached_;
}

CloudDistanceField CloudGeodesics::DistancesFrom(const Eigen::Vector3d& source,
                                                 Progress* progress) {
  double snap = 0;
  bool hole = false;
  const auto [snapped, node] = Snap(source, "source", -1, &snap, &hole);
  const Eigen::Vector3d point = hole ? source : snapped;
  Propagation& propagation =
      hole ? HolePropagationFrom(source, snap, node) : PropagationFrom(point, node);
  propagation.Run(-1, progress);
  field_source_ = point;
  CloudDistanceField field;
  field.source = point;
  field.stats = propagation.stats();
  field.node_distance_mm.resize(grid_.num_nodes());
  for (int i = 0; i < grid_.num_nodes(); ++i)
    field.node_distance_mm[i] = propagation.distance_mm(i);
  const Eigen::MatrixX3d& points = grid_.index().points();
  field_distance_.resize(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    field_distance_[i] =
        propagation.DistanceNear(grid_.node_of_point(i), points.row(i).transpose());
  if (options_.point_field.enabled)
    SweepPoints(point, hole ? RimNodes(source, snap, node) : std::vector<int>());
  field.point_distance_mm = field_distance_;
  return field;
}

// The per-point field (point_field.h) over field_distance_, which holds the
// grid's first-order values: seeded with them within seed_radius_cells of
// the source, where the grid's flowed paths are best and a sweep's wavefront
// is most curved, and on the whole rim of a hole the source lies in (the
// chords across it); `point`: the source on the surface (or in the hole).
// Where the two agree within agree_fraction the grid's value stays (its
// flowed paths are straighter than the sweep's graph, so its mean error is
// lower); where they do not, the grid has blurred a feature and the sweep's
// value is taken.
void CloudGeodesics::SweepPoints(const Eigen::Vector3d& point, const std::vector<int>& rim_nodes) {
  const Eigen::MatrixX3d& points = grid_.index().points();
  const double radius = options_.point_field.seed_radius_cells * grid_.cell_size_mm();
  std::vector<char> rim(static_cast<size_t>(grid_.num_nodes()), 0);
  for (const int n : rim_nodes) rim[static_cast<size_t>(n)] = 1;
  std::vector<PointSeed> seeds;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (std::isfinite(field_distance_[i]) &&
        (field_distance_[i] <= radius || rim[static_cast<size_t>(grid_.node_of_point(i))]))
      seeds.push_back({static_cast<int>(i), field_distance_[i]});
  const int nearest = grid_.index().Nearest(point);
  if (std::isfinite(field_distance_[nearest])) seeds.push_back({nearest, field_distance_[nearest]});
  const Eigen::VectorXd swept = PointDistanceField(options_.point_field, grid_, seeds);
  // A point no chord along the surface reaches (a lone noisy point, a
  // pocket): the nearest swept point on the same surface plus the straight
  // step, else its node's value.
  std::vector<int> near;
  std::vector<double> d2;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double cells = field_distance_[i];
    if (!std::isfinite(cells)) {  // unreached by the grid: the sweep's (maybe +inf too)
      field_distance_[i] = swept[i];
      continue;
    }
    if (std::isfinite(swept[i])) {
      const bool agree =
          std::abs(swept[i] - cells) <= options_.point_field.agree_fraction * swept[i];
      if (!agree) field_distance_[i] = swept[i];
      continue;
    }
    const Eigen::Vector3d x = points.row(i).transpose();
    grid_.index().Knn(x, 2 * options_.point_field.neighbours, &near, &d2);
    double best = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < near.size(); ++k)
      if (std::isfinite(swept[near[k]]) &&
          grid_.StepOnSurface(grid_.node_of_point(i), x, grid_.node_of_point(near[k]),
                              grid_.index().point(near[k])))
        best = std::min(best, swept[near[k]] + std::sqrt(d2[k]));
    if (std::isfinite(best)) field_distance_[i] = best;
  }
}

int CloudGeodesics::NearestOf(const Eigen::Vector3d& from, const std::vector<int>& targets,
                              const std::vector<double>& extra_mm, double* cost_mm) {
  const auto [a, node_a] = Snap(from, "from");
  Propagation& propagation = PropagationFrom(a, node_a);
  // A lower bound on each target's cost. A node's distance is the length of
  // a polyline from `a` to its site, so at least the chord; the first-order
  // distance at a point p of the node then falls short of |a - p| by at most
  // twice p's offset from the site. Targets are tried in order of the bound,
  // and the propagation never grows to one that cannot beat the best so far.
  const auto n = targets.size();
  std::vector<double> bound(n);
  std::vector<int> nodes(n);
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p = grid_.index().point(targets[i]);
    nodes[i] = grid_.node_of_point(targets[i]);
    bound[i] = (p - a).norm() - 2 * (p - grid_.site(nodes[i])).norm() + extra_mm[i];
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t x, size_t y) { return bound[x] < bound[y]; });
  *cost_mm = std::numeric_limits<double>::infinity();
  int best = -1;
  for (const size_t i : order) {
    if (bound[i] > *cost_mm) break;
    const int node = nodes[i];
    if (grid_.component(node) != grid_.component(node_a)) continue;
    propagation.Run(node);
    if (!propagation.settled(node)) continue;
    const double cost =
        propagation.DistanceNear(node, grid_.index().point(targets[i])) + extra_mm[i];
    // Equal costs go to the first target, as in the order given.
    if (cost < *cost_mm || (cost == *cost_mm && static_cast<int>(i) < best))
      *cost_mm = cost, best = static_cast<int>(i);
  }
  return best;
}

Eigen::VectorXd CloudGeodesics::DistancesAt(const Eigen::MatrixX3d& points) {
  if (!field_source_ || !cached_ || cached_->source() != *field_source_)
    throw InputError("geodesics: DistancesAt needs a distance field (DistancesFrom) first");
  cached_->Run(-1);
  const int component = grid_.component(cached_->source_node());
  Eigen::VectorXd out =
      Eigen::VectorXd::Constant(points.rows(), std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d x = points.row(i).transpose();
    if (!x.allFinite()) continue;
    // The nearest scan point if reached (the point field reaches pieces the
    // grid's links do not join, e.g. a cavity behind knife-edged lips),
    // else the nearest on the source's piece (skipping a small unreached
    // island).
    int q = grid_.LocatePoint(x);
    if (!std::isfinite(field_distance_[q])) q = grid_.LocatePoint(x, nullptr, component);
    const int node = grid_.node_of_point(q);
    const Eigen::Vector3d xq = grid_.index().point(q);
    const double change = cached_->DistanceNear(node, x) - cached_->DistanceNear(node, xq);
    out[i] = field_distance_[q] + (std::isfinite(change) ? change : (x - xq).norm());
  }
  return out;
}

CloudGeodesicPath CloudGeodesics::Between(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  double snap_a = 0, snap_b = 0;
  bool hole_a = false, hole_b = false;
  const auto [a, node_a] = Snap(from, "from", -1, &snap_a, &hole_a);
  const auto [b, node_b] = Snap(to, "to", grid_.component(node_a), &snap_b, &hole_b);
  if (grid_.component(node_a) != grid_.component(node_b)) {
    const auto& sizes = grid_.component_points();
    throw InputError(
        "from " + FormatPoint(from) + " to " + FormatPoint(to) +
        ": the points lie on separate pieces of the scan (" +
        std::to_string(sizes[static_cast<size_t>(grid_.component(node_a))]) + " and " +
        std::to_string(sizes[static_cast<size_t>(grid_.component(node_b))]) +
        " points) that no surface path connects; is one of them in an unscanned region?");
  }
  if (hole_a || hole_b)
    return BetweenAcrossHoles(from, to, node_a, node_b, snap_a, snap_b, hole_a, hole_b);
  Propagation& propagation = PropagationFrom(a, node_a);
  propagation.Run(node_b);
  if (!propagation.settled(node_b))
    throw InputError("from " + FormatPoint(from) + " to " + FormatPoint(to) +
                     ": no path over the scanned surface connects the two points");
  CloudGeodesicPath result;
  result.from_snap_mm = snap_a;
  result.to_snap_mm = snap_b;
  result.from_unscanned = hole_a;
  result.to_unscanned = hole_b;
  result.nodes_settled = propagation.stats().settled;
  result.propagated_length_mm = propagation.DistanceNear(node_b, b);
  std::vector<int> hints;
  Eigen::MatrixX3d path = propagation.Path(node_b, &hints);
  if (path.rows() < 2) {  // the target's site is the source itself
    path.resize(2, 3);
    path.row(0) = a.transpose();
    hints.assign(2, node_b);
  }
  path.row(path.rows() - 1) = b.transpose();  // the true end instead of the node's site
  result.length_mm = Polished(&path, &hints, &result);
  result.points = std::move(path);
  return result;
}

double CloudGeodesics::Polished(Eigen::MatrixX3d* path, std::vector<int>* hints,
                                CloudGeodesicPath* result) const {
  std::vector<TangentPlane> planes;  // unknown until asked for
  if (options_.polish && (path->row(0) - path->row(path->rows() - 1)).norm() > 0) {
    const double spacing =
        options_.polish_spacing_mm > 0 ? options_.polish_spacing_mm : 0.5 * grid_.cell_size_mm();
    Piece piece;
    piece.hints = *hints;
    piece.samples = ResamplePolyline(*path, spacing, &piece.hints);
    FillMissingPlanes(grid_, piece.samples, &piece.hints, &piece.planes);
    CurvatureFlowReport report;
    report.converged = true;
    result->polish_rejected =
        !PolishPiece(options_.polish_flow, grid_, options_.polish_splits, &piece, &report);
    result->polish_converged = report.converged;
    result->polish_iterations = report.iterations;
    *path = std::move(piece.samples);
    *hints = std::move(piece.hints);
    planes = std::move(piece.planes);
  }
  FillMissingPlanes(grid_, *path, hints, &planes);
  return SurfaceCurveLength(*path, planes);
}

}  // namespace bespoke
