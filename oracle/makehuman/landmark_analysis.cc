#include "oracle/makehuman/landmark_analysis.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "measure/tape/convex_hull_2d.h"
#include "oracle/truth/mesh_section.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Vec = Eigen::Vector3d;

class Analysis {
 public:
  Analysis(const TriangleMesh& mesh, const std::map<std::string, Vec>& joints)
      : mesh_(mesh), joints_(joints) {
    stature_ = mesh.vertices.col(2).maxCoeff();
  }

  Vec Joint(const std::string& name) const {
    const auto it = joints_.find(name);
    if (it == joints_.end()) throw InputError("landmark analysis: no joint '" + name + "'");
    return it->second;
  }
  Vec V(int v) const { return mesh_.vertices.row(v).transpose(); }
  double stature() const { return stature_; }
  int num_vertices() const { return static_cast<int>(mesh_.num_vertices()); }

  // The vertex maximising `score` among those passing `keep`; InputError
  // naming `what` when none passes.
  int Best(const std::function<bool(const Vec&)>& keep,
           const std::function<double(const Vec&)>& score, const char* what) const {
    int best = -1;
    double best_score = -kInf;
    for (int v = 0; v < mesh_.num_vertices(); ++v) {
      const Vec p = V(v);
      if (!keep(p)) continue;
      const double s = score(p);
      if (s > best_score) best_score = s, best = v;
    }
    if (best < 0) throw InputError(std::string("landmark analysis: no vertex for ") + what);
    return best;
  }

  int Nearest(const Vec& p) const {
    Eigen::Index i = 0;
    (mesh_.vertices.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&i);
    return static_cast<int>(i);
  }

  // y of the spine chain at height z (joints pelvis .. head), dividing the
  // trunk's front from its back on the mid-sagittal seam.
  double SpineY(double z) const {
    std::vector<Vec> chain;
    for (const char* n : {"pelvis", "spine-4", "spine-3", "spine-2", "spine-1", "neck", "head"})
      chain.push_back(Joint(n));
    std::sort(chain.begin(), chain.end(), [](const Vec& a, const Vec& b) { return a.z() < b.z(); });
    if (z <= chain.front().z()) return chain.front().y();
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      if (z <= chain[i + 1].z()) {
        const double t = (z - chain[i].z()) / (chain[i + 1].z() - chain[i].z());
        return chain[i].y() + t * (chain[i + 1].y() - chain[i].y());
      }
    return chain.back().y();
  }
  bool Seam(const Vec& p) const { return std::abs(p.x()) < 0.5; }
  bool FrontSeam(const Vec& p) const { return Seam(p) && p.y() > SpineY(p.z()); }
  bool BackSeam(const Vec& p) const { return Seam(p) && p.y() < SpineY(p.z()); }

  int SeamVertexNear(double z, bool front) const {
    return Best([&](const Vec& p) { return front ? FrontSeam(p) : BackSeam(p); },
                [&](const Vec& p) { return -std::abs(p.z() - z); }, "a seam vertex");
  }

  // The horizontal section loop at height z nearest to `anchor` (a point
  // inside the body part).
  SectionLoop LoopAt(double z, const Vec& anchor) const {
    return LoopIn(Vec(0, 0, z), Vec::UnitZ(), anchor);
  }
  SectionLoop LoopIn(const Vec& point, const Vec& normal, const Vec& anchor) const {
    const auto loops = SectionLoops(mesh_, point, normal);
    const int i = NearestLoop(loops, anchor);
    if (i < 0) throw InputError("landmark analysis: empty section");
    return loops[static_cast<std::size_t>(i)];
  }
  Vec TrunkAnchor(double z) const { return Vec(0, SpineY(z) + 30, z); }

  static Vec Extreme(const SectionLoop& loop, const Vec& direction) {
    Eigen::Index i = 0;
    (loop.points * direction).maxCoeff(&i);
    return loop.points.row(i).transpose();
  }

 private:
  const TriangleMesh& mesh_;
  const std::map<std::string, Vec>& joints_;
  double stature_ = 0;
};

// The point of `axis_from` -> `axis_to` at height z (clamped to the segment).
Vec AxisAt(const Vec& a, const Vec& b, double z) {
  const double t = std::clamp((z - a.z()) / (b.z() - a.z()), 0.0, 1.0);
  return a + t * (b - a);
}

// The armpit: the lowest vertex height at which the horizontal section of
// the upper arm joins the trunk's (a saddle of the height function).
Vec Armpit(const Analysis& an, const TriangleMesh& mesh) {
  const Vec s = an.Joint("r-shoulder"), e = an.Joint("r-elbow");
  std::vector<double> heights;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Vec p = an.V(v);
    if (p.x() > 0 && p.z() > e.z() && p.z() < s.z()) heights.push_back(p.z());
  }
  std::sort(heights.begin(), heights.end());
  auto merged = [&](double z) {
    const auto loops = SectionLoops(mesh, Vec(0, 0, z), Vec::UnitZ());
    return NearestLoop(loops, an.TrunkAnchor(z)) == NearestLoop(loops, AxisAt(s, e, z));
  };
  // Just above each vertex height; separate near the elbow, merged near the shoulder.
  std::size_t lo = 0, hi = heights.size() - 1;
  if (heights.empty() || merged(heights[lo] + 1e-6) || !merged(heights[hi] + 1e-6))
    throw InputError("landmark analysis: the arm does not separate from the trunk");
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (merged(heights[mid] + 1e-6) ? hi : lo) = mid;
  }
  const double z = heights[hi];
  return an.V(an.Best([&](const Vec& p) { return p.x() > 0 && p.z() == z; },
                      [&](const Vec& p) { return -std::abs(p.x() - s.x()); }, "the armpit"));
}

// The deepest concavity of `loop` (projected on xy) among points passing
// `keep`: the point farthest inside the loop's convex hull.
Vec DeepestPocket(const SectionLoop& loop, const std::function<bool(const Vec&)>& keep) {
  Eigen::MatrixX2d xy = loop.points.leftCols<2>();
  const std::vector<int> hull = ConvexHullIndices(xy);
  double best = -1;
  Vec best_point = Vec::Zero();
  for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
    const Vec p = loop.points.row(i).transpose();
    if (!keep(p)) continue;
    const double depth = DepthInsideHull(xy, hull, p.head<2>());
    if (depth > best) best = depth, best_point = p;
  }
  if (best < 0) throw InputError("landmark analysis: no armpit fold found");
  return best_point;
}

// The side neck point: in the coronal section through the neck joint, the
// concave corner where the side of the neck meets the top of the shoulder:
// the contour point farthest below the chord from the neck's side (3 % of
// stature above the neck joint) to the shoulder point.
Vec SideNeck(const Analysis& an, const Vec& acromion) {
  const Vec neck = an.Joint("neck");
  const SectionLoop coronal = an.LoopIn(neck, Vec::UnitY(), neck);
  const double top_z = neck.z() + 0.03 * an.stature();
  Vec top(0, neck.y(), -kInf);  // the neck's side at top_z: the outermost crossing
  for (Eigen::Index i = 0; i < coronal.points.rows(); ++i) {
    const Vec a = coronal.points.row(i), b = coronal.points.row((i + 1) % coronal.points.rows());
    if ((a.z() - top_z) * (b.z() - top_z) > 0 || a.z() == b.z() || a.x() <= 0) continue;
    const Vec c = a + (top_z - a.z()) / (b.z() - a.z()) * (b - a);
    if (c.x() > top.x() || !std::isfinite(top.z())) top = c;
  }
  if (!std::isfinite(top.z()))
    throw InputError("landmark analysis: no neck side in the coronal section");
  const Eigen::Vector2d p1(top.x(), top.z()), p2(acromion.x(), acromion.z());
  Eigen::Vector2d down(p2.y() - p1.y(), p1.x() - p2.x());  // perpendicular to the chord
  if (down.y() > 0) down = -down;
  down.normalize();
  double best = -kInf;
  Vec corner = top;
  for (Eigen::Index i = 0; i < coronal.points.rows(); ++i) {
    const Vec p = coronal.points.row(i);
    if (p.x() < top.x() - 10 || p.x() > acromion.x() || p.z() < acromion.z() - 5 ||
        p.z() > top_z + 5)
      continue;
    const double depth = (Eigen::Vector2d(p.x(), p.z()) - p1).dot(down);
    if (depth > best) best = depth, corner = p;
  }
  return corner;
}

using Result = std::map<std::string, AnalysedLandmark>;

void Put(Result* r, const std::string& name, const Vec& p, int vertex) {
  (*r)[name] = AnalysedLandmark{p, vertex};
}

// The right-side (x > 0) rules; the left side runs them on the mirror image.
void RightSide(const Analysis& an, const TriangleMesh& mesh, const Result& centre, Result* r) {
  const double h = an.stature();
  const Vec s = an.Joint("r-shoulder"), e = an.Joint("r-elbow"), w = an.Joint("r-hand");
  const Vec k = an.Joint("r-knee"), a = an.Joint("r-ankle"), hip_joint = an.Joint("r-upper-leg");
  auto put_vertex = [&](const char* name, int v) { Put(r, name, an.V(v), v); };
  auto put_point = [&](const char* name, const Vec& p) { Put(r, name, p, an.Nearest(p)); };

  const Vec armpit = Armpit(an, mesh);
  put_point("armpit", armpit);
  const int acromion = an.Best(
      [&](const Vec& p) {
        return std::abs(p.y() - s.y()) < 25 && p.z() > s.z() - 20 && p.x() > s.x() - 60;
      },
      [&](const Vec& p) { return (p.x() - s.x()) + (p.z() - s.z()); }, "the shoulder point");
  put_vertex("shoulder", acromion);
  put_point("side_neck", SideNeck(an, an.V(acromion)));
  const double fold_z = armpit.z() + 0.25 * (an.V(acromion).z() - armpit.z());
  const SectionLoop fold = an.LoopAt(fold_z, an.TrunkAnchor(fold_z));
  auto near_armpit = [&](const Vec& p) {
    return p.x() > armpit.x() - 70 && p.x() < armpit.x() + 40;
  };
  put_point("axilla_front", DeepestPocket(fold, [&](const Vec& p) {
              return near_armpit(p) && p.y() > armpit.y();
            }));
  put_point("axilla_back", DeepestPocket(fold, [&](const Vec& p) {
              return near_armpit(p) && p.y() < armpit.y();
            }));
  put_vertex("bust", an.Best(
                         [&](const Vec& p) {
                           return p.x() > 0.3 * armpit.x() && p.x() < armpit.x() &&
                                  p.z() < armpit.z() - 0.02 * h && p.z() > armpit.z() - 0.10 * h;
                         },
                         [](const Vec& p) { return p.y(); }, "the bust point"));
  // Thigh: 20 mm below the crotch, the lateral extreme of the right leg.
  const double thigh_z = centre.at("crotch").position.z() - 20;
  put_point("thigh",
            Analysis::Extreme(an.LoopAt(thigh_z, AxisAt(hip_joint, k, thigh_z)), Vec::UnitX()));
  auto near_leg = [&](const Vec& p, const Vec& joint, double r) {
    return p.x() > 0 && (p.head<2>() - joint.head<2>()).norm() < r;
  };
  put_vertex(
      "knee",
      an.Best([&](const Vec& p) { return std::abs(p.z() - k.z()) < 15 && near_leg(p, k, 120); },
              [](const Vec& p) { return p.y(); }, "the knee"));
  put_vertex("calf", an.Best(
                         [&](const Vec& p) {
                           const double t = (p.z() - a.z()) / (k.z() - a.z());
                           return t > 0.3 && t < 0.9 && near_leg(p, AxisAt(a, k, p.z()), 110);
                         },
                         [](const Vec& p) { return -p.y(); }, "the calf"));
  auto ankle_slab = [&](const Vec& p) {
    return std::abs(p.z() - a.z()) < 12 && near_leg(p, a, 70) && std::abs(p.y() - a.y()) < 30;
  };
  put_vertex("ankle_inside",
             an.Best(
                 ankle_slab, [](const Vec& p) { return -p.x(); }, "the inner ankle"));
  put_vertex("ankle_outside",
             an.Best(
                 ankle_slab, [](const Vec& p) { return p.x(); }, "the outer ankle"));
  const Vec arm_axis = (w - s).normalized(), forearm = (w - e).normalized();
  put_vertex("elbow", an.Best(
                          [&](const Vec& p) {
                            return std::abs((p - e).dot(arm_axis)) < 15 && (p - e).norm() < 90;
                          },
                          [](const Vec& p) { return -p.y(); }, "the elbow"));
  put_vertex("wrist", an.Best(
                          [&](const Vec& p) {
                            return std::abs((p - w).dot(forearm)) < 10 && (p - w).norm() < 70;
                          },
                          [](const Vec& p) { return -p.y(); }, "the wrist"));
  const Vec upper = (e - s).normalized();
  const double t_mid =
      0.5 * ((an.V(acromion) - s).dot(upper) + (r->at("elbow").position - s).dot(upper));
  const Vec mid = s + t_mid * upper;
  const Vec outward = (Vec::UnitX() - Vec::UnitX().dot(upper) * upper).normalized();
  put_vertex("upper_arm", an.Best(
                              [&](const Vec& p) {
                                return std::abs((p - mid).dot(upper)) < 10 && (p - mid).norm() < 90;
                              },
                              [&](const Vec& p) { return p.dot(outward); }, "the upper arm"));
}

Result Centre(const Analysis& an, const TriangleMesh& mesh) {
  Result r;
  const double h = an.stature();
  auto put_vertex = [&](const char* name, int v) { Put(&r, name, an.V(v), v); };
  put_vertex("crown", an.Best([](const Vec&) { return true; }, [](const Vec& p) { return p.z(); },
                              "the crown"));
  put_vertex("crotch", an.Best([&](const Vec& p) { return an.Seam(p) && p.z() > 0.3 * h; },
                               [](const Vec& p) { return -p.z(); }, "the crotch"));
  const Vec neck = an.Joint("neck");
  put_vertex("back_neck", an.SeamVertexNear(neck.z(), /*front=*/false));
  put_vertex("front_neck", an.Best(
                               [&](const Vec& p) {
                                 return an.FrontSeam(p) && p.z() > neck.z() - 80 &&
                                        p.z() < neck.z();
                               },
                               [](const Vec& p) { return -p.y(); }, "the front neck point"));
  (void)mesh;
  return r;
}

// Trunk levels: under-bust, waist, hip, middle hip (need the bust and crotch).
void TrunkLevels(const Analysis& an, const Vec& bust, Result* r) {
  const double h = an.stature();
  // Under-bust fold: on the vertical through the bust point, the front
  // profile f(z) (most forward point per 5 mm band) bends sharply where the
  // underside of the breast meets the chest wall: the band with the largest
  // second difference f(z + 10) - 2 f(z) + f(z - 10), searched from 1 % to
  // 8 % of stature below the bust point.
  const SectionLoop sagittal = an.LoopIn(bust, Vec::UnitX(), bust - Vec(0, 20, 0));
  auto front_at = [&](double z) {  // most forward crossing of the loop with height z
    double best_y = -kInf;
    const Eigen::Index n = sagittal.points.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vec a = sagittal.points.row(i), b = sagittal.points.row((i + 1) % n);
      if ((a.z() - z) * (b.z() - z) > 0 || a.z() == b.z()) continue;
      best_y = std::max(best_y, a.y() + (z - a.z()) / (b.z() - a.z()) * (b.y() - a.y()));
    }
    return best_y;
  };
  double fold_z = bust.z() - 0.04 * h, best_bend = -kInf;
  for (double z = bust.z() - 0.08 * h; z < bust.z() - 0.01 * h; z += 2.5) {
    const double bend = front_at(z + 10) - 2 * front_at(z) + front_at(z - 10);
    if (std::isfinite(bend) && bend > best_bend) best_bend = bend, fold_z = z;
  }
  const int fold = an.SeamVertexNear(fold_z, true);
  const double under_z = fold_z;
  Put(r, "under_bust", an.V(fold), fold);
  const double crotch_z = r->at("crotch").position.z();
  // Hip: height of the most posterior point of the buttocks.
  const int buttock = an.Best(
      [&](const Vec& p) {
        return p.z() > crotch_z && p.z() < under_z - 0.1 * h && std::abs(p.x()) < 150 &&
               p.y() < an.SpineY(p.z());
      },
      [](const Vec& p) { return -p.y(); },
      ("the buttocks (crotch " + std::to_string(crotch_z) + ", under-bust " +
       std::to_string(under_z) + ")")
          .c_str());
  const double hip_z = an.V(buttock).z();
  // Waist: smallest trunk girth between the hip and the under-bust.
  double waist_z = hip_z, best = kInf;
  for (double z = hip_z + 0.03 * h; z < under_z - 0.02 * h; z += 3) {
    const double girth = LoopHullPerimeter(an.LoopAt(z, an.TrunkAnchor(z)), Vec::UnitZ());
    if (girth < best) best = girth, waist_z = z;
  }
  for (const auto& [name, z, front] :
       {std::tuple{"front_waist", waist_z, true}, std::tuple{"back_waist", waist_z, false},
        std::tuple{"hip_back", hip_z, false},
        std::tuple{"middle_hip_front", 0.5 * (hip_z + waist_z), true}}) {
    const int v = an.SeamVertexNear(z, front);
    Put(r, name, an.V(v), v);
  }
  for (const auto& [name, z] : {std::pair{"side_waist", waist_z}, std::pair{"hip", hip_z}}) {
    const Vec p = Analysis::Extreme(an.LoopAt(z, an.TrunkAnchor(z)), Vec::UnitX());
    Put(r, std::string(name) + "_right", p, an.Nearest(p));
  }
}

TriangleMesh Mirrored(const TriangleMesh& mesh) {
  TriangleMesh m = mesh;
  m.vertices.col(0) *= -1;
  m.faces.col(1).swap(m.faces.col(2));
  return m;
}

std::map<std::string, Vec> MirroredJoints(const std::map<std::string, Vec>& joints) {
  std::map<std::string, Vec> out;
  for (const auto& [key, position] : joints) {
    std::string name = key;
    Vec p = position;
    if (name.rfind("l-", 0) == 0)
      name[0] = 'r';
    else if (name.rfind("r-", 0) == 0)
      name[0] = 'l';
    p.x() = -p.x();
    out[name] = p;
  }
  return out;
}

}  // namespace

std::map<std::string, AnalysedLandmark> AnalyseMakeHumanLandmarks(
    const TriangleMesh& mesh, const std::map<std::string, Eigen::Vector3d>& joints) {
  const Analysis an(mesh, joints);
  Result result = Centre(an, mesh);
  const TriangleMesh mirror_mesh = Mirrored(mesh);
  const auto mirror_joints = MirroredJoints(joints);
  const Analysis mirror(mirror_mesh, mirror_joints);
  for (const auto& [side, analysis, m] :
       {std::tuple{"_right", &an, &mesh}, std::tuple{"_left", &mirror, &mirror_mesh}}) {
    Result one;
    RightSide(*analysis, *m, result, &one);
    for (auto [name, l] : one) {
      if (m != &mesh) l.position.x() = -l.position.x();
      result[name + side] = l;
    }
  }
  TrunkLevels(an, result.at("bust_right").position, &result);
  // The side levels were analysed on the right; mirror them to the left.
  for (const char* name : {"side_waist", "hip"}) {
    AnalysedLandmark l = result.at(std::string(name) + "_right");
    l.position.x() = -l.position.x();
    l.vertex = an.Nearest(l.position);
    result[std::string(name) + "_left"] = l;
  }
  return result;
}

}  // namespace bespoke
