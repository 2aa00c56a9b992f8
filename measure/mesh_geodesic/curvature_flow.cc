#include "measure/mesh_geodesic/curvature_flow.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {

void CurvatureFlowOptions::Check() const {
  if (max_iterations < 1)
    throw InputError("curvature flow: max_iterations must be >= 1, got " +
                     std::to_string(max_iterations));
  if (!(tolerance_mm > 0) || !std::isfinite(tolerance_mm))
    throw InputError("curvature flow: tolerance_mm must be > 0, got " +
                     std::to_string(tolerance_mm));
  if (!(max_step_segments > 0) || !std::isfinite(max_step_segments))
    throw InputError("curvature flow: max_step_segments must be > 0, got " +
                     std::to_string(max_step_segments));
  if (!(replan_distance_mm >= 0) || !std::isfinite(replan_distance_mm))
    throw InputError("curvature flow: replan_distance_mm must be >= 0, got " +
                     std::to_string(replan_distance_mm));
}

namespace {

using Basis = Eigen::Matrix<double, 3, 2>;

// Scratch of one flow: the planes of the interior samples and the block
// factorisation. Index k is interior sample k + 1.
struct FlowSystem {
  std::vector<Basis> tangent;            // T_k, zero for a held sample
  std::vector<Eigen::Vector3d> foot;     // q_i for all m samples
  std::vector<Eigen::Matrix2d> inverse;  // inverses of the Schur complements D_k
  std::vector<Eigen::Vector2d> rhs;      // y_k, then the solution u_k
};

// Estimates the plane of every interior sample and projects the sample onto
// it (q_i). Returns the number of samples without a plane.
int EstimatePlanes(const TangentPlaneSource& source, const Eigen::MatrixX3d& p, double replan,
                   std::vector<int>* hints, std::vector<TangentPlane>* planes, FlowSystem* sys) {
  const Eigen::Index m = p.rows();
  int held = 0;
  sys->foot[0] = p.row(0).transpose();
  sys->foot[m - 1] = p.row(m - 1).transpose();
  for (Eigen::Index i = 1; i + 1 < m; ++i) {
    const Eigen::Vector3d x = p.row(i).transpose();
    int no_hint = -1;
    int* hint = hints ? &(*hints)[static_cast<size_t>(i)] : &no_hint;
    Basis& t = sys->tangent[static_cast<size_t>(i - 1)];
    TangentPlane plane;
    TangentPlane* cached = planes ? &(*planes)[static_cast<size_t>(i)] : nullptr;
    if (cached && cached->normal.squaredNorm() > 0 &&
        (x - cached->point).squaredNorm() <= replan * replan) {
      plane = *cached;
    } else if (!source.PlaneAt(x, hint, &plane) || !(plane.normal.norm() > 0) ||
               !plane.point.allFinite() || !plane.normal.allFinite()) {
      t.setZero();
      sys->foot[i] = x;
      if (cached) cached->normal.setZero();
      ++held;
      continue;
    } else if (cached) {
      *cached = plane;
    }
    const Eigen::Vector3d n = plane.normal.normalized();
    sys->foot[i] = x - n * n.dot(x - plane.point);
    t.col(0) = n.unitOrthogonal();
    t.col(1) = n.cross(t.col(0));
  }
  return held;
}

// Solves the block-tridiagonal system for the in-plane offsets u_k (left in
// sys->rhs) by block Cholesky / Thomas: O(m).
void SolveOffsets(FlowSystem* sys) {
  const size_t n = sys->tangent.size();
  const auto& t = sys->tangent;
  const auto& q = sys->foot;
  for (size_t k = 0; k < n; ++k)  // r_k = T_k^T (q_{i-1} - 2 q_i + q_{i+1})
    sys->rhs[k] = t[k].transpose() * (q[k] - 2.0 * q[k + 1] + q[k + 2]);
  Eigen::Matrix2d d = 2.0 * Eigen::Matrix2d::Identity();
  sys->inverse[0] = d.inverse();
  for (size_t k = 1; k < n; ++k) {
    const Eigen::Matrix2d c = t[k - 1].transpose() * t[k];  // C_{k-1}
    const Eigen::Matrix2d l = c.transpose() * sys->inverse[k - 1];
    d = 2.0 * Eigen::Matrix2d::Identity() - l * c;
    sys->inverse[k] = d.inverse();
    sys->rhs[k] += l * sys->rhs[k - 1];
  }
  sys->rhs[n - 1] = sys->inverse[n - 1] * sys->rhs[n - 1];
  for (size_t k = n - 1; k-- > 0;) {
    const Eigen::Matrix2d c = t[k].transpose() * t[k + 1];  // C_k
    sys->rhs[k] = sys->inverse[k] * (sys->rhs[k] + c * sys->rhs[k + 1]);
  }
}

}  // namespace

double PolylineLength(const Eigen::MatrixX3d& samples) {
  double length = 0;
  for (Eigen::Index i = 1; i < samples.rows(); ++i)
    length += (samples.row(i) - samples.row(i - 1)).norm();
  return length;
}

double SurfaceCurveLength(const Eigen::MatrixX3d& samples,
                          const std::vector<TangentPlane>& planes) {
  BESPOKE_CHECK(planes.size() == static_cast<size_t>(samples.rows()), "planes per sample");
  double length = 0;
  for (Eigen::Index i = 1; i < samples.rows(); ++i) {
    const Eigen::Vector3d chord = (samples.row(i) - samples.row(i - 1)).transpose();
    const double c = chord.norm();
    const Eigen::Vector3d& a = planes[static_cast<size_t>(i - 1)].normal;
    const Eigen::Vector3d& b = planes[static_cast<size_t>(i)].normal;
    if (c == 0 || a.squaredNorm() == 0 || b.squaredNorm() == 0) {
      length += c;
      continue;
    }
    const Eigen::Vector3d turn = (a.dot(b) < 0 ? -b : b) - a;
    const double s = std::min(1.0, 0.5 * std::abs(turn.dot(chord)) / c);
    length += s > 1e-8 ? c * std::asin(s) / s : c;
  }
  return length;
}

void FillMissingPlanes(const TangentPlaneSource& source, const Eigen::MatrixX3d& samples,
                       std::vector<int>* hints, std::vector<TangentPlane>* planes) {
  const size_t m = static_cast<size_t>(samples.rows());
  if (planes->size() != m) {
    TangentPlane unknown;
    unknown.normal.setZero();
    planes->resize(m, unknown);
  }
  for (size_t i = 0; i < m; ++i) {
    if ((*planes)[i].normal.squaredNorm() > 0) continue;
    int no_hint = -1;
    int* hint = hints && hints->size() == m ? &(*hints)[i] : &no_hint;
    if (!source.PlaneAt(samples.row(static_cast<Eigen::Index>(i)).transpose(), hint, &(*planes)[i]))
      (*planes)[i].normal.setZero();
  }
}

CurvatureFlowReport FlowPolyline(const CurvatureFlowOptions& options,
                                 const TangentPlaneSource& source, Eigen::MatrixX3d* samples,
                                 std::vector<int>* hints, std::vector<TangentPlane>* planes) {
  options.Check();
  if (samples == nullptr || samples->rows() < 2)
    throw InputError("curvature flow: a polyline needs at least 2 samples");
  if (!samples->allFinite())
    throw InputError("curvature flow: the polyline has non-finite coordinates");
  const Eigen::Index m = samples->rows();
  if (hints && hints->size() != static_cast<size_t>(m))
    throw InputError("curvature flow: " + std::to_string(hints->size()) + " hints for " +
                     std::to_string(m) + " samples");
  if (planes && planes->size() != static_cast<size_t>(m))
    throw InputError("curvature flow: " + std::to_string(planes->size()) + " planes for " +
                     std::to_string(m) + " samples");
  CurvatureFlowReport report;
  if (m <= 2) {
    report.converged = true;
    report.length_mm = PolylineLength(*samples);
    return report;
  }
  const size_t n = static_cast<size_t>(m - 2);
  FlowSystem sys;
  sys.tangent.resize(n);
  sys.foot.resize(static_cast<size_t>(m));
  sys.inverse.resize(n);
  sys.rhs.resize(n);
  Eigen::MatrixX3d& p = *samples;
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    report.iterations = iteration;
    report.samples_without_plane +=
        EstimatePlanes(source, p, options.replan_distance_mm, hints, planes, &sys);
    SolveOffsets(&sys);
    // Trust region on the in-plane slide (|T u| = |u|, T orthonormal).
    const double max_step =
        options.max_step_segments * PolylineLength(p) / static_cast<double>(m - 1);
    double largest = 0;
    for (const auto& u : sys.rhs) largest = std::max(largest, u.norm());
    const double scale = largest > max_step && largest > 0 ? max_step / largest : 1.0;
    double move = 0;
    for (size_t k = 0; k < n; ++k) {
      const Eigen::Vector3d next = sys.foot[k + 1] + scale * (sys.tangent[k] * sys.rhs[k]);
      const Eigen::Index i = static_cast<Eigen::Index>(k + 1);
      move = std::max(move, (next - p.row(i).transpose()).norm());
      p.row(i) = next.transpose();
    }
    report.last_move_mm = move;
    if (move <= options.tolerance_mm) {
      report.converged = true;
      break;
    }
  }
  if (!p.allFinite()) throw InternalError("curvature flow: the polyline became non-finite");
  report.length_mm = PolylineLength(p);
  return report;
}

Eigen::MatrixX3d ResamplePolyline(const Eigen::MatrixX3d& samples, double max_spacing_mm,
                                  std::vector<int>* hints) {
  if (samples.rows() < 2) throw InputError("resample: a polyline needs at least 2 samples");
  if (!(max_spacing_mm > 0) || !std::isfinite(max_spacing_mm))
    throw InputError("resample: max_spacing_mm must be > 0");
  if (hints && hints->size() != static_cast<size_t>(samples.rows()))
    throw InputError("resample: hints and samples differ in count");
  const Eigen::Index m = samples.rows();
  std::vector<double> arc(static_cast<size_t>(m), 0.0);
  for (Eigen::Index i = 1; i < m; ++i)
    arc[i] = arc[i - 1] + (samples.row(i) - samples.row(i - 1)).norm();
  const double total = arc.back();
  const Eigen::Index segments =
      std::max<Eigen::Index>(1, static_cast<Eigen::Index>(std::ceil(total / max_spacing_mm)));
  Eigen::MatrixX3d out(segments + 1, 3);
  std::vector<int> out_hints(static_cast<size_t>(segments + 1), -1);
  Eigen::Index j = 0;  // current old segment [j, j+1]
  for (Eigen::Index s = 0; s <= segments; ++s) {
    const double target = total * static_cast<double>(s) / static_cast<double>(segments);
    while (j + 2 < m && arc[j + 1] < target) ++j;
    const double len = arc[j + 1] - arc[j];
    const double t = len > 0 ? std::clamp((target - arc[j]) / len, 0.0, 1.0) : 0.0;
    out.row(s) = (1 - t) * samples.row(j) + t * samples.row(j + 1);
    if (hints) out_hints[s] = (*hints)[static_cast<size_t>(t < 0.5 ? j : j + 1)];
  }
  out.row(0) = samples.row(0);
  out.row(segments) = samples.row(m - 1);
  if (hints) {
    out_hints.front() = hints->front();
    out_hints.back() = hints->back();
    *hints = std::move(out_hints);
  }
  return out;
}

}  // namespace bespoke
