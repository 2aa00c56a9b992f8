#include "measure/geodesic/cloud_geodesics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scanners/core/errors.h"

namespace bespoke {

void CloudGeodesicsOptions::Check() const {
  grid.Check();
  propagation.Check();
  polish_flow.Check();
  if (!(max_snap_distance_mm >= 0) || !std::isfinite(max_snap_distance_mm))
    throw InputError("geodesics: max_snap_distance_mm must be >= 0");
  if (!(polish_spacing_mm >= 0) || !std::isfinite(polish_spacing_mm))
    throw InputError("geodesics: polish_spacing_mm must be >= 0");
}

namespace {

const CloudGeodesicsOptions& Checked(const CloudGeodesicsOptions& options) {
  options.Check();
  return options;
}

std::string Format(const Eigen::Vector3d& x) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f)", x.x(), x.y(), x.z());
  return text;
}

}  // namespace

CloudGeodesics::CloudGeodesics(const CloudGeodesicsOptions& options,
                               const Eigen::MatrixX3d& points, Progress* progress)
    : options_(Checked(options)), grid_(options.grid, points, progress) {}

CloudGeodesics::~CloudGeodesics() = default;

std::pair<Eigen::Vector3d, int> CloudGeodesics::Snap(const Eigen::Vector3d& x,
                                                     const std::string& what,
                                                     int component) const {
  if (!x.allFinite()) throw InputError(what + ": coordinates must be finite numbers");
  const double limit = options_.max_snap_distance_mm > 0 ? options_.max_snap_distance_mm
                                                         : std::max(10.0, 3 * grid_.cell_size_mm());
  double distance = 0;
  int node = grid_.LocateNode(x, &distance, component);
  if (component < 0) {
    const auto& sizes = grid_.component_points();
    if (sizes[static_cast<size_t>(grid_.component(node))] < 0.05 * sizes[0]) {
      double main_distance = 0;
      const int main = grid_.LocateNode(x, &main_distance, 0);
      if (grid_.component(main) == 0 && main_distance <= limit) {
        node = main;
        distance = main_distance;
      }
    }
  }
  if (distance > limit) {
    char text[160];
    std::snprintf(text, sizeof text,
                  " is %.1f mm from the nearest scan point (at most %.1f mm allowed); "
                  "give coordinates on the surface, in the scan's frame and units (mm)",
                  distance, limit);
    throw InputError(what + " " + Format(x) + text);
  }
  return {grid_.surface(node).PlaneAt(x).point, node};
}

Propagation& CloudGeodesics::PropagationFrom(const Eigen::Vector3d& source, int node) {
  if (!cached_ || cached_->source_node() != node || cached_->source() != source)
    cached_ = std::make_unique<Propagation>(options_.propagation, grid_, source, node);
  return *cached_;
}

CloudDistanceField CloudGeodesics::DistancesFrom(const Eigen::Vector3d& source,
                                                 Progress* progress) {
  const auto [point, node] = Snap(source, "source");
  Propagation& propagation = PropagationFrom(point, node);
  propagation.Run(-1, progress);
  field_source_ = point;
  CloudDistanceField field;
  field.source = point;
  field.stats = propagation.stats();
  field.node_distance_mm.resize(grid_.num_nodes());
  for (int i = 0; i < grid_.num_nodes(); ++i)
    field.node_distance_mm[i] = propagation.distance_mm(i);
  const Eigen::MatrixX3d& points = grid_.index().points();
  field.point_distance_mm.resize(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    field.point_distance_mm[i] =
        propagation.DistanceNear(grid_.node_of_point(i), points.row(i).transpose());
  return field;
}

Eigen::VectorXd CloudGeodesics::DistancesAt(const Eigen::MatrixX3d& points) {
  if (!field_source_ || !cached_ || cached_->source() != *field_source_)
    throw InputError("geodesics: DistancesAt needs a distance field (DistancesFrom) first");
  cached_->Run(-1);
  Eigen::VectorXd out(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d x = points.row(i).transpose();
    // Prefer the source's piece of the scan over a small unreached island.
    out[i] = x.allFinite()
                 ? cached_->DistanceNear(
                       grid_.LocateNode(x, nullptr, grid_.component(cached_->source_node())), x)
                 : std::numeric_limits<double>::infinity();
  }
  return out;
}

CloudGeodesicPath CloudGeodesics::Between(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const auto [a, node_a] = Snap(from, "from");
  const auto [b, node_b] = Snap(to, "to", grid_.component(node_a));
  if (grid_.component(node_a) != grid_.component(node_b)) {
    const auto& sizes = grid_.component_points();
    throw InputError(
        "from " + Format(from) + " to " + Format(to) +
        ": the points lie on separate pieces of the scan (" +
        std::to_string(sizes[static_cast<size_t>(grid_.component(node_a))]) + " and " +
        std::to_string(sizes[static_cast<size_t>(grid_.component(node_b))]) +
        " points) that no surface path connects; is one of them in an unscanned region?");
  }
  Propagation& propagation = PropagationFrom(a, node_a);
  propagation.Run(node_b);
  if (!propagation.settled(node_b))
    throw InputError("from " + Format(from) + " to " + Format(to) +
                     ": no path over the scanned surface connects the two points");
  CloudGeodesicPath result;
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
  std::vector<TangentPlane> planes;  // unknown until asked for
  if (options_.polish && (a - b).norm() > 0) {
    const double spacing = options_.polish_spacing_mm > 0 ? options_.polish_spacing_mm
                                                          : 0.5 * grid_.cell_size_mm();
    std::vector<int> flowed_hints = hints;
    Eigen::MatrixX3d flowed = ResamplePolyline(path, spacing, &flowed_hints);
    std::vector<TangentPlane> flowed_planes;
    FillMissingPlanes(grid_, flowed, &flowed_hints, &flowed_planes);
    const CurvatureFlowReport report =
        FlowPolyline(options_.polish_flow, grid_, &flowed, &flowed_hints, &flowed_planes);
    result.polish_converged = report.converged;
    result.polish_iterations = report.iterations;
    // As in the propagation: a flow that cut between unlinked nodes (through
    // a gap) is undone and the propagated path, which follows links, is kept.
    bool on_surface = true;
    for (size_t i = 1; i < flowed_hints.size() && on_surface; ++i)
      on_surface = grid_.StepOnSurface(flowed_hints[i - 1], flowed.row(i - 1).transpose(),
                                       flowed_hints[i], flowed.row(i).transpose());
    result.polish_rejected = !on_surface;
    if (on_surface) {
      path = std::move(flowed);
      hints = std::move(flowed_hints);
      planes = std::move(flowed_planes);
    }
  }
  FillMissingPlanes(grid_, path, &hints, &planes);
  result.length_mm = SurfaceCurveLength(path, planes);
  result.points = std::move(path);
  return result;
}

}  // namespace bespoke
