// The parametric body's legs and arms (see parametric_body.h for the
// construction). Right side built, left side mirrored.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "oracle/body/parametric_build.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke::parametric {
namespace {

size_t IndexOf(const std::vector<double>& levels, double value) {
  for (size_t i = 0; i < levels.size(); ++i) {
    if (std::abs(levels[i] - value) < 1e-9) return i;
  }
  throw InternalError("parametric body: no ring at level " + std::to_string(value));
}

// Levels from `keys` (ascending by `at`) walking from the last key down to
// the first (legs) with at most `spacing` between rings, counting sideways
// moves too.
std::vector<double> LevelsDown(const std::vector<SectionKey>& keys, double spacing) {
  std::vector<double> out;
  for (size_t k = keys.size() - 1; k > 0; --k) {
    const double move =
        std::max(keys[k].at - keys[k - 1].at, SidewaysChange(keys[k].section, keys[k - 1].section));
    const int steps = std::max(1, static_cast<int>(std::ceil(move / spacing)));
    for (int s = 1; s <= steps; ++s) {
      out.push_back(s == steps ? keys[k - 1].at
                               : keys[k].at + (keys[k - 1].at - keys[k].at) * s / steps);
    }
  }
  return out;
}

void AddLimbGirth(Build* b, const std::string& name, const std::vector<int>& ring,
                  const Section& section, const Eigen::Vector3d& point,
                  const Eigen::Vector3d& normal, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& axis_u, const Eigen::Vector3d& axis_v) {
  GirthRing g;
  g.origin = origin;
  g.axis_u = axis_u;
  g.axis_v = axis_v;
  g.measurement = name;
  g.ring = ring;
  g.section = section;
  g.plane_point = point;
  g.plane_normal = normal;
  g.limb = true;
  b->girths.push_back(g);
}

}  // namespace

void BuildLegs(Build* b) {
  const BodyLayout& L = *b->layout;
  const int n = b->n, q = n / 4;
  const double spacing = L.options.ring_spacing_mm;
  // The right leg's top loop: the right lobe of the crotch ring from its
  // lateral point forwards, the bridge from front to back, then the lobe's
  // back half: n vertices, lateral / front / medial / back at 0, q, 2q, 3q.
  std::vector<int> first;
  for (int j = 0; j <= q; ++j) first.push_back(b->torso[0][static_cast<size_t>(j)]);
  for (int v : b->bridge) first.push_back(v);
  for (int j = 3 * q; j < n; ++j) first.push_back(b->torso[0][static_cast<size_t>(j)]);
  BESPOKE_CHECK(static_cast<int>(first.size()) == n, "parametric body: crotch loop size");
  std::vector<double> levels = Subdivide(L.z_crotch, L.z_thigh, spacing, 3);
  for (double z : LevelsDown(L.leg, spacing)) levels.push_back(z);
  std::vector<std::vector<Eigen::Vector3d>> rings;
  for (double z : levels) {
    const std::vector<Eigen::Vector2d> pts = InterpolateSection(L.leg, z).Sample(q);
    const double u = std::clamp((L.z_crotch - z) / (L.z_crotch - L.z_thigh), 0.0, 1.0);
    const double w = (1 - u) * (1 - u);  // crotch loop weight: 1 at the crotch, 0 at the thigh
    std::vector<Eigen::Vector3d> ring;
    for (int m = 0; m < n; ++m) {
      const Eigen::Vector3d top = b->mesh.position(first[static_cast<size_t>(m)]);
      const Eigen::Vector2d p = w * top.head<2>() + (1 - w) * pts[static_cast<size_t>(m)];
      ring.push_back({p.x(), p.y(), z});
    }
    rings.push_back(ring);
  }
  // Flat sole on z = 0: inner rings towards the sole's centre, then a pole.
  const Section& sole = L.leg.front().section;
  const Eigen::Vector3d centre(sole.cu, sole.cv, 0);
  const std::vector<Eigen::Vector3d> outline = rings.back();
  for (double s : {0.72, 0.44, 0.18}) {
    std::vector<Eigen::Vector3d> ring;
    for (const Eigen::Vector3d& p : outline) ring.push_back(centre + s * (p - centre));
    rings.push_back(ring);
  }
  b->part_starts.push_back({b->mesh.num_vertices(), BodyPart::kLegRight});
  const auto right = AddTube(b, first, rings, centre);
  b->part_starts.push_back({b->mesh.num_vertices(), BodyPart::kLegLeft});
  AddMirroredTube(b, first, right);
  // Girth rings and datum points (right side; the left is mirrored).
  for (const SectionKey& key : L.leg) {
    if (key.girth.empty()) continue;
    AddLimbGirth(b, key.girth, right[IndexOf(levels, key.at)], key.section,
                 {key.section.cu, key.section.cv, key.at}, Eigen::Vector3d::UnitZ(), {0, 0, key.at},
                 Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
  }
  const auto vertex = [&](double z, int m) {
    return right[IndexOf(levels, z)][static_cast<size_t>(m)];
  };
  const auto centre_at = [&](double z) {
    const Section c = InterpolateSection(L.leg, std::min(z, L.z_thigh));
    return Eigen::Vector3d(c.cu, c.cv, z);
  };
  b->joints["r-upper-leg"] = centre_at(L.z_crotch + 0.03 * L.options.stature_mm);
  b->joints["r-knee"] = centre_at(L.z_knee);
  b->joints["r-ankle"] = centre_at(L.z_ankle);
  b->landmarks["thigh_right"] = vertex(L.z_thigh, 3 * q);
  b->landmarks["knee_right"] = vertex(L.z_knee, q);
  b->landmarks["calf_right"] = vertex(L.z_calf, 3 * q);
  b->landmarks["ankle_inside_right"] = vertex(L.z_malleolus_inside, 2 * q);
  b->landmarks["ankle_outside_right"] = vertex(L.z_malleolus_outside, 0);
}

namespace {

// The right arm's centre path: a bend of `theta` about a pivot `radius`
// below the armscye's centre, then straight along the arm.
struct ArmPath {
  Eigen::Vector3d start;  // armscye centre
  double radius = 0, theta = 0;
  double bend() const { return radius * theta; }
  double Phi(double s) const { return theta == 0 ? 0 : std::min(s, bend()) / radius; }
  Eigen::Vector3d T(double s) const {
    const double f = Phi(s);
    return {std::cos(f), 0, -std::sin(f)};
  }
  Eigen::Vector3d U(double s) const {
    const double f = Phi(s);
    return {std::sin(f), 0, std::cos(f)};
  }
  Eigen::Vector3d Centre(double s) const {
    const Eigen::Vector3d pivot = start - radius * Eigen::Vector3d::UnitZ();
    return pivot + radius * U(s) + std::max(0.0, s - bend()) * T(s);
  }
};

// The armscye loop of the right arm, starting at the acromion and running
// forwards: top edge, front edge down, bottom edge backwards, back edge up.
std::vector<int> ArmscyeLoop(const Build& b) {
  const int h = b.h, ia = b.ring_armpit, is = b.ring_shoulder;
  const auto v = [&b](int ring, int column) {
    return b.torso[static_cast<size_t>(ring)][static_cast<size_t>(b.Col(column))];
  };
  std::vector<int> loop;
  for (int c = 0; c <= h; ++c) loop.push_back(v(is, c));
  for (int i = is - 1; i > ia; --i) loop.push_back(v(i, h));
  for (int c = h; c >= -h; --c) loop.push_back(v(ia, c));
  for (int i = ia + 1; i < is; ++i) loop.push_back(v(i, -h));
  for (int c = -h; c < 0; ++c) loop.push_back(v(is, c));
  return loop;
}

// Everything the right arm's rings are built from.
struct ArmPlan {
  ArmPath path;
  std::vector<Eigen::Vector3d>
      local;  // armscye loop: (t along +x, u along +z, v along +y) about path.start
  std::vector<SectionKey> keys;     // arm keys, `at` on the centre path
  double blend = 0;                 // the loop has blended into the sections by here
  std::vector<double> stations;     // ring positions on the centre path
  std::vector<double> cap_scale;    // per station: 1, or the fingertip cap's shrink
  double s_fingers = 0, s_tip = 0;  // last key, fingertip
  Eigen::Vector3d d;                // the arm's straight direction
  std::vector<std::pair<double, Eigen::Vector3d>> normals;  // ring plane normals by station
};

// The bend, the loop in its local frame, and the keys on the centre path.
ArmPlan PlanArm(const Build& b, const std::vector<int>& loop) {
  const BodyLayout& L = *b.layout;
  const double H = L.options.stature_mm;
  ArmPlan plan;
  ArmPath& path = plan.path;
  path.start.setZero();
  for (int v : loop) path.start += b.mesh.position(v) / static_cast<double>(loop.size());
  double lowest = 0;
  for (int v : loop) {
    const Eigen::Vector3d d = b.mesh.position(v) - path.start;
    plan.local.push_back({d.x(), d.z(), d.y()});
    lowest = std::min(lowest, d.z());
  }
  path.radius = -lowest + 0.004 * H;  // the pivot sits just below the armpit
  path.theta = (90 - L.options.arm_abduction_deg) * kPi / 180;
  plan.d = path.T(path.bend() + 1);
  // Arm keys from lateral-line distances to centre-path positions.
  const double u_avg = 0.5 * (plan.local[0].y() + L.arm.front().section.a);
  const double lateral_bend = path.bend() + u_avg * path.theta;
  plan.blend = std::max(path.bend() + 0.006 * H, 0.045 * H);
  plan.keys = L.arm;
  for (SectionKey& key : plan.keys) {
    key.at =
        key.at <= lateral_bend ? key.at / (1 + u_avg / path.radius) : key.at - u_avg * path.theta;
  }
  auto& keys = plan.keys;
  BESPOKE_CHECK(keys[1].girth == "upper_arm_girth" && keys[2].girth == "elbow_girth" &&
                    keys[4].girth == "wrist_girth",
                "parametric body: arm keys changed");
  keys[1].at =
      std::max(keys[1].at, plan.blend + 0.02 * H);  // the girth ring must be past the blend
  keys[0].at = std::min(keys[0].at, 0.6 * keys[1].at);
  // The forearm's back (the ulna's ridge) runs straight from the elbow point
  // to the wrist point: shift the wrist and hand back by the depth change.
  const double shift =
      (keys[2].section.cv - keys[2].section.back.b) - (keys[4].section.cv - keys[4].section.back.b);
  keys[3].section.cv += 0.5 * shift;
  for (size_t k = 4; k < keys.size(); ++k) keys[k].section.cv += shift;
  for (size_t k = 1; k < keys.size(); ++k)
    BESPOKE_CHECK(keys[k].at > keys[k - 1].at, "parametric body: arm keys out of order");
  plan.s_fingers = keys.back().at;
  plan.s_tip = plan.s_fingers + (L.arm_tip_lateral - L.arm.back().at);
  return plan;
}

// Stations: the bend by the outer line's spacing, then every key, then the fingertip cap.
void PlanStations(ArmPlan* plan, double spacing) {
  const ArmPath& path = plan->path;
  if (path.theta > 0) {
    const int steps = std::max(
        2, static_cast<int>(std::ceil(path.theta * (path.radius + plan->local[0].y()) / spacing)));
    for (int s = 1; s <= steps; ++s) plan->stations.push_back(path.bend() * s / steps);
  }
  std::vector<double> stops = {plan->blend};
  for (const SectionKey& key : plan->keys) stops.push_back(key.at);
  std::sort(stops.begin(), stops.end());
  double from = plan->stations.empty() ? 0.0 : plan->stations.back();
  for (double stop : stops) {
    if (stop <= from + 1e-9) continue;
    for (double s : Subdivide(from, stop, spacing)) plan->stations.push_back(s);
    from = stop;
  }
  const Section& fingers = plan->keys.back().section;
  const double reach = std::max({fingers.a, fingers.front.b, plan->s_tip - plan->s_fingers});
  const int cap = std::max(3, static_cast<int>(std::ceil(kPi / 2 * reach / spacing)));
  plan->cap_scale.assign(plan->stations.size(), 1.0);
  for (int k = 1; k < cap; ++k) {
    const double psi = kPi / 2 * k / cap;
    plan->stations.push_back(plan->s_fingers + (plan->s_tip - plan->s_fingers) * std::sin(psi));
    plan->cap_scale.push_back(std::cos(psi));
  }
}

// Girth rings lie in the catalogue's planes: upper arm perpendicular to
// shoulder -> elbow, elbow perpendicular to shoulder -> wrist, wrist
// perpendicular to elbow -> wrist. Those depend on the datum points on the
// rings themselves (A: the acromion); a few fixed-point steps settle them
// (the angles are small). Other rings' normals are interpolated.
void PlanGirthPlanes(ArmPlan* plan, const Eigen::Vector3d& A) {
  const ArmPath& path = plan->path;
  const Eigen::Vector3d d = plan->d;
  const auto back_point = [&](const SectionKey& key, const Eigen::Vector3d& normal) {
    const Eigen::Quaterniond r = Eigen::Quaterniond::FromTwoVectors(d, normal);
    return Eigen::Vector3d(path.Centre(key.at) + key.section.cu * (r * path.U(key.at)) +
                           (key.section.cv - key.section.back.b) * (r * Eigen::Vector3d::UnitY()));
  };
  const auto& keys = plan->keys;
  Eigen::Vector3d n_wrist = d, n_elbow = d;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::Vector3d W = back_point(keys[4], n_wrist);
    n_elbow = (W - A).normalized();
    n_wrist = (W - back_point(keys[2], n_elbow)).normalized();
  }
  const Eigen::Vector3d n_upper = (back_point(keys[2], n_elbow) - A).normalized();
  plan->normals = {{plan->blend, d},      {keys[1].at, n_upper},
                   {keys[2].at, n_elbow}, {keys[3].at, (n_elbow + n_wrist).normalized()},
                   {keys[4].at, n_wrist}, {keys[5].at, d}};
}

Eigen::Vector3d NormalAt(const ArmPlan& plan, double s) {
  const auto& normals = plan.normals;
  if (s <= normals.front().first || s >= normals.back().first) return plan.d;
  size_t i = 0;
  while (normals[i + 1].first < s) ++i;
  const double t = (s - normals[i].first) / (normals[i + 1].first - normals[i].first);
  return ((1 - t) * normals[i].second + t * normals[i + 1].second).normalized();
}

// The ring at station k: the armscye loop blended into the section, in the
// plane through the centre path (turned to its girth plane past the blend).
std::vector<Eigen::Vector3d> ArmRing(const ArmPlan& plan, size_t k, int segments) {
  const ArmPath& path = plan.path;
  const double s = plan.stations[k];
  const double x = std::min(1.0, s / plan.blend), w = x * x * (3 - 2 * x);
  Section section = InterpolateSection(plan.keys, std::min(s, plan.s_fingers));
  if (plan.cap_scale[k] < 1) section = section.Scaled(plan.cap_scale[k]);
  const std::vector<Eigen::Vector2d> pts = section.Sample(segments / 4);
  const Eigen::Quaterniond r =
      Eigen::Quaterniond::FromTwoVectors(path.T(s), s < plan.blend ? path.T(s) : NormalAt(plan, s));
  const Eigen::Vector3d c = path.Centre(s), T = path.T(s);
  const Eigen::Vector3d U = r * path.U(s), F = r * Eigen::Vector3d::UnitY();
  std::vector<Eigen::Vector3d> ring;
  for (int m = 0; m < segments; ++m) {
    const Eigen::Vector3d& l = plan.local[static_cast<size_t>(m)];
    const Eigen::Vector2d& p = pts[static_cast<size_t>(m)];
    ring.push_back(c + (1 - w) * l.x() * T + ((1 - w) * l.y() + w * p.x()) * U +
                   ((1 - w) * l.z() + w * p.y()) * F);
  }
  return ring;
}

}  // namespace

void BuildArms(Build* b) {
  const ParametricBodyOptions& o = b->layout->options;
  const int M = o.arm_segments, q = M / 4;
  const std::vector<int> loop = ArmscyeLoop(*b);
  BESPOKE_CHECK(static_cast<int>(loop.size()) == M, "parametric body: armscye loop size");
  ArmPlan plan = PlanArm(*b, loop);
  PlanStations(&plan, o.ring_spacing_mm);
  PlanGirthPlanes(&plan, b->mesh.position(loop[0]));
  std::vector<std::vector<Eigen::Vector3d>> rings;
  for (size_t k = 0; k < plan.stations.size(); ++k) rings.push_back(ArmRing(plan, k, M));
  b->part_starts.push_back({b->mesh.num_vertices(), BodyPart::kArmRight});
  const auto right = AddTube(b, loop, rings, plan.path.Centre(plan.s_tip));
  b->part_starts.push_back({b->mesh.num_vertices(), BodyPart::kArmLeft});
  AddMirroredTube(b, loop, right);
  const auto ring_at = [&](double s) { return right[IndexOf(plan.stations, s)]; };
  for (const SectionKey& key : plan.keys) {
    if (key.girth.empty()) continue;
    const Eigen::Vector3d n = NormalAt(plan, key.at);
    const Eigen::Quaterniond r = Eigen::Quaterniond::FromTwoVectors(plan.path.T(key.at), n);
    AddLimbGirth(b, key.girth, ring_at(key.at), key.section, plan.path.Centre(key.at), n,
                 plan.path.Centre(key.at), r * plan.path.U(key.at), r * Eigen::Vector3d::UnitY());
  }
  b->joints["r-shoulder"] = plan.path.start;
  b->joints["r-elbow"] = plan.path.Centre(plan.keys[2].at);
  b->joints["r-hand"] = plan.path.Centre(plan.keys[4].at);
  b->landmarks["upper_arm_right"] = ring_at(plan.keys[1].at)[0];
  b->landmarks["elbow_right"] = ring_at(plan.keys[2].at)[static_cast<size_t>(3 * q)];
  b->landmarks["wrist_right"] = ring_at(plan.keys[4].at)[static_cast<size_t>(3 * q)];
  // The lateral line actually built, acromion to wrist (for the report).
  double lateral = 0;
  Eigen::Vector3d previous = b->mesh.position(loop[0]);
  for (size_t k = 0; k <= IndexOf(plan.stations, plan.keys[4].at); ++k) {
    const Eigen::Vector3d p = b->mesh.position(right[k][0]);
    lateral += (p - previous).norm();
    previous = p;
  }
  b->derived["arm_lateral_line_mm"] = lateral;
  b->derived["arm_bend_radius_mm"] = plan.path.radius;
  b->derived["armhole_columns"] = 2 * b->h;
}

}  // namespace bespoke::parametric
