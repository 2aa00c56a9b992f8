#include "measure/mesh_geodesic/path_projection.h"

#include <cmath>
#include <limits>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {

double CutBetween(const MeshSurface& surface, const MeshFoot& from, const MeshFoot& to,
                  const Eigen::Vector3d& plane_normal, int max_faces,
                  std::vector<Eigen::Vector3d>* points, bool* fell_back) {
  *fell_back = false;
  const Eigen::Vector3d chord = to.point - from.point;
  const double chord2 = chord.squaredNorm();
  if (from.face == to.face || chord2 == 0) {
    if (points) points->push_back(to.point);
    return std::sqrt(chord2);
  }
  const Eigen::Vector3d c = chord / std::sqrt(chord2);
  Eigen::Vector3d n = plane_normal - plane_normal.dot(c) * c;
  const size_t first = points ? points->size() : 0;
  auto fail = [&]() {
    *fell_back = true;
    if (points) {
      points->resize(first);
      points->push_back(to.point);
    }
    return std::sqrt(chord2);
  };
  if (!(n.norm() > 1e-12)) return fail();
  n.normalize();
  const Eigen::MatrixX3d& v = surface.mesh().vertices;
  const Eigen::MatrixX3i& f = surface.mesh().faces;
  // Sign of a vertex against the plane; zero counts as positive (a symbolic
  // perturbation), so the plane never passes exactly through a vertex.
  auto side = [&](int vertex) { return n.dot(v.row(vertex).transpose() - from.point) >= 0; };
  double length = 0;
  Eigen::Vector3d at = from.point;
  int face = from.face, previous = -1;
  for (int step = 0; step < max_faces; ++step) {
    int exit = -1;
    double best = -std::numeric_limits<double>::infinity();
    Eigen::Vector3d crossing;
    for (int k = 0; k < 3; ++k) {
      const int a = f(face, k), b = f(face, (k + 1) % 3);
      if (side(a) == side(b)) continue;
      const int across = surface.adjacent_face(face, k);
      if (previous >= 0 && across == previous) continue;  // the edge we came in through
      const Eigen::Vector3d pa = v.row(a).transpose(), pb = v.row(b).transpose();
      const double da = n.dot(pa - from.point), db = n.dot(pb - from.point);
      const Eigen::Vector3d x = pa + (da / (da - db)) * (pb - pa);
      const double progress = (x - from.point).dot(chord);
      if (progress > best) {
        best = progress;
        exit = k;
        crossing = x;
      }
    }
    if (exit < 0 || best > chord2 * (1 + 1e-9) || best < -1e-9 * chord2) return fail();
    length += (crossing - at).norm();
    if (points) points->push_back(crossing);
    at = crossing;
    previous = face;
    face = surface.adjacent_face(face, exit);
    if (face < 0) return fail();
    if (face == to.face) {
      length += (to.point - at).norm();
      if (points) points->push_back(to.point);
      return length;
    }
  }
  return fail();
}

ProjectedPath ProjectPolyline(const MeshSurface& surface, const Eigen::MatrixX3d& samples,
                              std::vector<int>* hints, const Eigen::Vector3d* before,
                              bool keep_points, int max_faces) {
  const Eigen::Index m = samples.rows();
  if (m < 1 || hints == nullptr || hints->size() != static_cast<size_t>(m))
    throw InputError("path projection: " + std::to_string(m) + " samples need as many hints");
  ProjectedPath out;
  out.cumulative.assign(static_cast<size_t>(m), 0.0);
  std::vector<MeshFoot> feet(static_cast<size_t>(m));
  for (Eigen::Index i = 0; i < m; ++i)
    feet[static_cast<size_t>(i)] =
        surface.ClosestPoint(samples.row(i).transpose(), &(*hints)[static_cast<size_t>(i)]);
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d>* keep = keep_points ? &points : nullptr;
  if (keep_points) points.push_back(feet[0].point);
  auto sample = [&](Eigen::Index i) -> Eigen::Vector3d {
    return i < 0 ? *before : Eigen::Vector3d(samples.row(i).transpose());
  };
  const Eigen::Index lowest = before ? -1 : 0;
  for (Eigen::Index i = 1; i < m; ++i) {
    const MeshFoot& a = feet[static_cast<size_t>(i - 1)];
    const MeshFoot& b = feet[static_cast<size_t>(i)];
    // The osculating triple centred on s_i, or the last one available.
    Eigen::Index centre = i + 1 < m ? i : i - 1;
    Eigen::Vector3d plane = Eigen::Vector3d::Zero();
    if (centre - 1 >= lowest && centre + 1 < m) {
      const Eigen::Vector3d e1 = sample(centre) - sample(centre - 1);
      const Eigen::Vector3d e2 = sample(centre + 1) - sample(centre);
      const Eigen::Vector3d cross = e1.cross(e2);
      if (cross.norm() > 1e-4 * e1.norm() * e2.norm()) plane = cross;
    }
    if (plane.squaredNorm() == 0)  // straight: the normal section through the chord
      plane = (b.point - a.point).cross(surface.NormalAt(a) + surface.NormalAt(b));
    bool fell_back = false;
    const size_t kept = keep ? keep->size() : 0;
    double piece = CutBetween(surface, a, b, plane, max_faces, keep, &fell_back);
    // A foot can land on the wrong side of a thin part (an ear, a finger):
    // a projected piece much longer or shorter than its floating segment is
    // not the projection of that segment; the floating segment's length
    // stands in.
    const double floating = (sample(i) - sample(i - 1)).norm();
    if (piece > 1.5 * floating + 1e-12 || 1.5 * piece < floating - 1e-12) {
      fell_back = true;
      piece = floating;
      if (keep) {
        keep->resize(kept);
        keep->push_back(b.point);
      }
    }
    out.cumulative[static_cast<size_t>(i)] = out.cumulative[static_cast<size_t>(i - 1)] + piece;
    out.fallbacks += fell_back;
  }
  out.length = out.cumulative.back();
  if (keep_points) {
    out.points.resize(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i)
      out.points.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  }
  return out;
}

}  // namespace bespoke
