// The parametric body: torso grid, assembly, landmarks and girth levels.
// Legs and arms are in parametric_limbs.cc; the layout (heights and key
// sections) in parametric_layout.cc.
#include "oracle/body/parametric_body.h"

#include <algorithm>
#include <cmath>

#include "measure/tape/convex_hull_2d.h"
#include "oracle/body/mesh_checks.h"
#include "oracle/body/parametric_build.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace parametric {
namespace {

// Torso ring heights: crotch .. armpit by spacing, the armhole band in a
// fixed number of steps, then up to the dome start by spacing and sideways
// change, then the dome. Records the rings of named keys.
void PlanTorsoLevels(Build* b, int band_steps) {
  const BodyLayout& L = *b->layout;
  const double spacing = L.options.ring_spacing_mm;
  std::vector<double>& z = b->torso_z;
  z = {L.z_crotch};
  const auto name_of = [](const SectionKey& key, size_t index) {
    return key.girth.empty() ? "key" + std::to_string(index) : key.girth;
  };
  // The crotch-to-hip blend gets at least 4 steps.
  for (double v : Subdivide(L.z_crotch, L.z_hip, spacing, 4)) z.push_back(v);
  for (size_t k = 0; k < L.torso.size(); ++k) {
    const SectionKey& key = L.torso[k];
    b->torso_key_ring[name_of(key, k)] = static_cast<int>(z.size()) - 1;
    if (k + 1 == L.torso.size()) break;
    const SectionKey& next = L.torso[k + 1];
    if (key.girth == "chest_girth") {  // the armhole band: exactly band_steps rings
      b->ring_armpit = static_cast<int>(z.size()) - 1;
      for (int s = 1; s <= band_steps; ++s)
        z.push_back(key.at + (next.at - key.at) * s / band_steps);
      b->ring_shoulder = static_cast<int>(z.size()) - 1;
      continue;
    }
    const double move = std::max(next.at - key.at, SidewaysChange(key.section, next.section));
    const int steps = std::max(1, static_cast<int>(std::ceil(move / spacing)));
    for (int s = 1; s <= steps; ++s) z.push_back(key.at + (next.at - key.at) * s / steps);
  }
  BESPOKE_CHECK(std::abs(z[static_cast<size_t>(b->ring_shoulder)] - L.z_shoulder) < 1e-9,
                "parametric body: the shoulder key does not follow the chest key");
}

// The figure-of-eight bottom ring at the crotch: column j of the right lobe
// (j in [-N/4, N/4]) at arc-length fraction along the lobe ellipse from its
// lateral point; the left lobe mirrors it.
std::vector<Eigen::Vector2d> CrotchRing(const BodyLayout& L, int n) {
  const double lx = L.lobe_x, ly = L.lobe_y, rx = L.lobe_rx, ry = L.lobe_ry;
  const double psi_front = std::acos(-lx / rx);
  const auto lobe = [&](double psi) {
    return Eigen::Vector2d(lx + rx * std::cos(psi), ly + ry * std::sin(psi));
  };
  const ArcLengthTable table(lobe, 0.0, psi_front);
  const int q = n / 4;
  std::vector<Eigen::Vector2d> ring(static_cast<size_t>(n));
  for (int j = 0; j <= q; ++j) {
    Eigen::Vector2d p = lobe(table.ParameterAt(static_cast<double>(j) / q));
    if (j == q) p.x() = 0;  // exactly on the midline
    ring[static_cast<size_t>(j)] = p;
    ring[static_cast<size_t>((n - j) % n)] = {p.x(),
                                              2 * ly - p.y()};  // back half of the right lobe
  }
  for (int j = q + 1; j < 3 * q; ++j) {  // left lobe: mirror of column n/2 - j
    const Eigen::Vector2d& r = ring[static_cast<size_t>(((n / 2 - j) % n + n) % n)];
    ring[static_cast<size_t>(j)] = {-r.x(), r.y()};
  }
  return ring;
}

bool InHole(const Build& b, int ring, int column) {
  if (ring <= b.ring_armpit || ring >= b.ring_shoulder) return false;
  const auto near = [&](int c) {
    const int d = ((column - c) % b.n + b.n) % b.n;
    return d < b.h || d > b.n - b.h;
  };
  return near(0) || near(b.n / 2);
}

void AddTorsoFaces(Build* b) {
  const int rings = static_cast<int>(b->torso.size());
  for (int i = 0; i + 1 < rings; ++i) {
    const bool band = i >= b->ring_armpit && i < b->ring_shoulder;
    for (int j = 0; j < b->n; ++j) {
      const int jn = b->Col(j + 1);
      if (band) {
        const int sj = ((j + b->n / 2) % b->n) - b->n / 2;  // signed column in [-N/2, N/2)
        const int sl = ((j) % b->n) - b->n / 2;             // relative to the left side
        if ((sj >= -b->h && sj < b->h) || (sl >= -b->h && sl < b->h)) continue;
      }
      const int v[4] = {b->torso[i][j], b->torso[i][jn], b->torso[i + 1][jn], b->torso[i + 1][j]};
      BESPOKE_CHECK(v[0] >= 0 && v[1] >= 0 && v[2] >= 0 && v[3] >= 0,
                    "parametric body: torso quad misses a vertex");
      b->mesh.Quad(v[0], v[1], v[2], v[3]);
    }
  }
}

// An ellipsoidal cap over the last torso key (the head), closed at the crown.
void AddDome(Build* b) {
  const BodyLayout& L = *b->layout;
  const int n = b->n;
  const double spacing = L.options.ring_spacing_mm;
  const double z0 = L.z_dome, z1 = L.options.stature_mm;
  const double reach = std::max({L.dome.a, L.dome.front.b, L.dome.back.b, z1 - z0});
  const int steps = std::max(4, static_cast<int>(std::ceil(kPi / 2 * reach / spacing)));
  std::vector<int> previous = b->torso.back();
  for (int s = 1; s < steps; ++s) {
    const double phi = kPi / 2 * s / steps;
    const std::vector<Eigen::Vector2d> pts = L.dome.Scaled(std::cos(phi)).Sample(n / 4);
    std::vector<int> ring;
    for (const Eigen::Vector2d& p : pts)
      ring.push_back(b->mesh.Add({p.x(), p.y(), z0 + (z1 - z0) * std::sin(phi)}));
    for (int j = 0; j < n; ++j)
      b->SetMirror(ring[static_cast<size_t>(j)], ring[static_cast<size_t>(b->Col(n / 2 - j))]);
    b->mesh.Stitch(previous, ring);
    previous = ring;
  }
  b->crown = b->mesh.Add({0, L.dome.cv, z1});
  b->SetMirror(b->crown, b->crown);
  b->mesh.Fan(previous, b->crown);
}

}  // namespace

double SidewaysChange(const Section& x, const Section& y) {
  return std::max({std::abs(x.a - y.a) + std::abs(x.cu - y.cu),
                   std::abs((x.cv + x.front.b) - (y.cv + y.front.b)),
                   std::abs((x.cv - x.back.b) - (y.cv - y.back.b))});
}

void RefineGirthRings(Build* b, int min_segments) {
  std::vector<std::pair<std::pair<int, int>, std::vector<int>>> splits;
  const auto on_curve = [](const GirthRing& g, const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - g.origin;
    const Eigen::Vector2d uv(d.dot(g.axis_u), d.dot(g.axis_v)), centre(g.section.cu, g.section.cv);
    const Eigen::Vector2d q = centre + (uv - centre) / g.section.Gauge(uv);
    return Eigen::Vector3d(g.origin + q.x() * g.axis_u + q.y() * g.axis_v);
  };
  for (GirthRing& g : b->girths) {
    const int n = static_cast<int>(g.ring.size());
    const int k = (min_segments + n - 1) / n;
    if (k <= 1) continue;
    std::vector<int> refined;
    for (int i = 0; i < n; ++i) {
      const int a = g.ring[static_cast<size_t>(i)], c = g.ring[static_cast<size_t>((i + 1) % n)];
      const Eigen::Vector3d pa = b->mesh.position(a), pc = b->mesh.position(c);
      std::vector<int> inner, inner_left;
      refined.push_back(a);
      for (int j = 1; j < k; ++j) {
        const Eigen::Vector3d p = on_curve(g, pa + (pc - pa) * (static_cast<double>(j) / k));
        inner.push_back(b->mesh.Add(p));
        refined.push_back(inner.back());
        if (g.limb) {  // the left limb's ring: the exact mirror image
          inner_left.push_back(b->mesh.Add({-p.x(), p.y(), p.z()}));
          b->SetMirror(inner.back(), inner_left.back());
        }
      }
      splits.push_back({{a, c}, inner});
      if (g.limb) splits.push_back({{b->Mirror(a), b->Mirror(c)}, inner_left});
    }
    g.ring = refined;
  }
  b->mirror.resize(static_cast<size_t>(b->mesh.num_vertices()), -1);
  b->mesh.SplitEdges(splits);
}

void Build::SetMirror(int a, int b_) {
  const size_t need = static_cast<size_t>(std::max(a, b_)) + 1;
  if (mirror.size() < need) mirror.resize(need, -1);
  mirror[static_cast<size_t>(a)] = b_;
  mirror[static_cast<size_t>(b_)] = a;
}

std::vector<double> Subdivide(double from, double to, double spacing, int min_steps) {
  const int steps = std::max(min_steps, static_cast<int>(std::ceil(std::abs(to - from) / spacing)));
  std::vector<double> out;
  for (int s = 1; s <= steps; ++s) out.push_back(s == steps ? to : from + (to - from) * s / steps);
  return out;
}

void BuildTorso(Build* b) {
  const BodyLayout& L = *b->layout;
  const int n = b->n;
  // Armhole: h columns each side of the side column, band rings so that the
  // armscye loop has exactly arm_segments vertices: 2 (2h + band) = M.
  const int m = L.options.arm_segments;
  const auto chest = std::find_if(L.torso.begin(), L.torso.end(),
                                  [](const SectionKey& k) { return k.girth == "chest_girth"; });
  BESPOKE_CHECK(chest != L.torso.end(), "parametric body: no chest key");
  const double chest_step = chest->section.Perimeter() / n;
  b->h = std::clamp(static_cast<int>(std::lround(L.armhole_width / (2 * chest_step))), 3,
                    std::min(n / 8 - 1, (m / 2 - 8) / 2));
  const int band_steps = m / 2 - 2 * b->h;
  PlanTorsoLevels(b, band_steps);
  const std::vector<Eigen::Vector2d> crotch = CrotchRing(L, n);
  const double z_hip = L.z_hip;
  const int rings = static_cast<int>(b->torso_z.size());
  b->torso.assign(static_cast<size_t>(rings), std::vector<int>(static_cast<size_t>(n), -1));
  for (int i = 0; i < rings; ++i) {
    const double z = b->torso_z[static_cast<size_t>(i)];
    const std::vector<Eigen::Vector2d> pts = InterpolateSection(L.torso, z).Sample(n / 4);
    const double u = std::clamp((z - L.z_crotch) / (z_hip - L.z_crotch), 0.0, 1.0);
    const double w = (1 - u) * (1 - u);  // 1 at the crotch, 0 (with zero slope) at the hip
    const Section section = InterpolateSection(L.torso, z);
    const double tilt = InterpolateTilt(L.torso, z), c = std::cos(tilt), s = std::sin(tilt);
    for (int j = 0; j < n; ++j) {
      if (InHole(*b, i, j)) continue;
      const Eigen::Vector2d p =
          (1 - w) * pts[static_cast<size_t>(j)] + w * crotch[static_cast<size_t>(j)];
      // Turn the ring's plane about the line x || (0, cv, z), front down.
      const double dv = p.y() - section.cv;
      b->torso[i][j] = b->mesh.Add({p.x(), section.cv + c * dv, z - s * dv});
    }
  }
  // Mirror pairs: column j <-> n/2 - j.
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < n; ++j) {
      const int v = b->torso[i][j];
      if (v >= 0) b->SetMirror(v, b->torso[i][b->Col(n / 2 - j)]);
    }
  }
  // Crotch bridge: n/2 - 1 vertices on x = 0 from the front centre to the back.
  const Eigen::Vector3d front = b->mesh.position(b->torso[0][n / 4]);
  const Eigen::Vector3d back = b->mesh.position(b->torso[0][3 * n / 4]);
  for (int k = 1; k < n / 2; ++k) {
    const int v = b->mesh.Add(front + (back - front) * k / (n / 2.0));
    b->bridge.push_back(v);
    b->SetMirror(v, v);
  }
  AddTorsoFaces(b);
  AddDome(b);
}

std::vector<std::vector<int>> AddTube(Build* b, const std::vector<int>& first,
                                      const std::vector<std::vector<Eigen::Vector3d>>& rings,
                                      const Eigen::Vector3d& pole) {
  const size_t start = b->mesh.num_faces();
  std::vector<std::vector<int>> out;
  std::vector<int> previous = first;
  for (const auto& positions : rings) {
    BESPOKE_CHECK(positions.size() == first.size(), "parametric body: tube rings differ in length");
    out.push_back(b->mesh.AddRing(positions));
    b->mesh.Stitch(previous, out.back());
    previous = out.back();
  }
  const int tip = b->mesh.Add(pole);
  b->mesh.Fan(previous, tip);
  out.push_back({tip});
  b->mesh.OrientPatchLike(start);
  return out;
}

std::vector<std::vector<int>> AddMirroredTube(Build* b, const std::vector<int>& right_first,
                                              const std::vector<std::vector<int>>& right) {
  const size_t m = right_first.size();
  const auto reversed = [m](size_t k) { return (m - k) % m; };
  std::vector<int> first(m);
  for (size_t k = 0; k < m; ++k) first[k] = b->Mirror(right_first[reversed(k)]);
  std::vector<std::vector<Eigen::Vector3d>> rings;
  const auto mirrored = [b](int v) {
    Eigen::Vector3d p = b->mesh.position(v);
    p.x() = -p.x();
    return p;
  };
  for (size_t r = 0; r + 1 < right.size(); ++r) {
    std::vector<Eigen::Vector3d> ring(m);
    for (size_t k = 0; k < m; ++k) ring[k] = mirrored(right[r][reversed(k)]);
    rings.push_back(ring);
  }
  std::vector<std::vector<int>> left = AddTube(b, first, rings, mirrored(right.back()[0]));
  for (size_t r = 0; r + 1 < right.size(); ++r) {
    for (size_t k = 0; k < m; ++k) b->SetMirror(left[r][k], right[r][reversed(k)]);
  }
  b->SetMirror(left.back()[0], right.back()[0]);
  return left;
}

}  // namespace parametric

namespace {

using parametric::Build;

int TorsoRingAt(const Build& b, double z) {
  for (size_t i = 0; i < b.torso_z.size(); ++i) {
    if (std::abs(b.torso_z[i] - z) < 1e-9) return static_cast<int>(i);
  }
  throw InternalError("parametric body: no torso ring at z = " + std::to_string(z));
}

// Horizontal torso girth rings and the torso's datum points.
void AddTorsoLandmarksAndGirths(Build* b) {
  const BodyLayout& L = *b->layout;
  const int n = b->n, q = n / 4;
  for (const SectionKey& key : L.torso) {
    if (key.girth.empty()) continue;
    const int i = TorsoRingAt(*b, key.at);
    parametric::GirthRing g;
    g.measurement = key.girth;
    g.ring = b->torso[static_cast<size_t>(i)];
    g.section = key.section;
    g.plane_point = {key.section.cu, key.section.cv, key.at};
    g.plane_normal = {0, std::sin(key.tilt), std::cos(key.tilt)};
    // Ring point (u, v) -> (u, cv + (v - cv) cos t, at - (v - cv) sin t).
    const double c = std::cos(key.tilt), s = std::sin(key.tilt), cv = key.section.cv;
    g.origin = {0, cv * (1 - c), key.at + cv * s};
    g.axis_u = Eigen::Vector3d::UnitX();
    g.axis_v = {0, c, -s};
    b->girths.push_back(g);
  }
  const auto at = [b](double z, int column) {
    return b->torso[static_cast<size_t>(TorsoRingAt(*b, z))][static_cast<size_t>(b->Col(column))];
  };
  auto& lm = b->landmarks;
  lm["crown"] = b->crown;
  // The neck base ring (tilted) carries the back neck point (back centre),
  // the front neck point (front centre) and the side neck points (sides).
  const auto neck = std::find_if(L.torso.begin(), L.torso.end(),
                                 [](const SectionKey& k) { return k.girth == "neck_girth"; });
  BESPOKE_CHECK(neck != L.torso.end(), "parametric body: no neck key");
  lm["back_neck"] = at(neck->at, 3 * q);
  lm["front_neck"] = at(neck->at, q);
  lm["side_neck_right"] = at(neck->at, 0);
  lm["shoulder_right"] = at(L.z_shoulder, 0);
  lm["armpit_right"] = at(L.z_armpit, 0);
  // Axilla points: the lower front and back corners of the armscye, where
  // the arm meets the chest and the back, at armpit level (so the chest
  // girth plane through them is the full armpit ring).
  lm["axilla_front_right"] = at(L.z_armpit, b->h);
  lm["axilla_back_right"] = at(L.z_armpit, -b->h);
  lm["under_bust"] = at(L.z_under_bust, q);
  lm["front_waist"] = at(L.z_waist, q);
  lm["back_waist"] = at(L.z_waist, 3 * q);
  lm["side_waist_right"] = at(L.z_waist, 0);
  lm["middle_hip_front"] = at(L.z_middle_hip, q);
  lm["hip_back"] = at(L.z_hip, 3 * q);
  lm["hip_right"] = at(L.z_hip, 0);
  lm["crotch"] = b->bridge[b->bridge.size() / 2];
}

SurfacePoint AtVertex(const TriangleMesh& mesh, const std::vector<int>& face_of, int vertex) {
  SurfacePoint p;
  p.face = face_of[static_cast<size_t>(vertex)];
  BESPOKE_CHECK(p.face >= 0, "parametric body: landmark vertex without a face");
  for (int c = 0; c < 3; ++c) p.barycentric[c] = mesh.faces(p.face, c) == vertex ? 1.0 : 0.0;
  return p;
}

// "_right" -> "_left" at the end of a name ("" when the name has no side).
std::string LeftName(const std::string& name) {
  const std::string right = "_right";
  if (name.size() < right.size() ||
      name.compare(name.size() - right.size(), right.size(), right) != 0)
    return "";
  return name.substr(0, name.size() - right.size()) + "_left";
}

AnalyticGirth MakeGirth(const parametric::GirthRing& g, const TriangleMesh& mesh,
                        const std::string& side, const std::vector<int>& ring,
                        const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  AnalyticGirth out;
  out.measurement = g.measurement;
  out.side = side;
  out.ring = ring;
  out.plane_point = point;
  out.plane_normal = normal;
  out.girth_mm = g.section.Perimeter();
  // The tape round the ring: its convex hull in the plane (the ring itself
  // where it is convex; the bust's dips into the cleavage).
  const Eigen::Vector3d u = normal.unitOrthogonal(), w = normal.cross(u);
  Eigen::MatrixX2d in_plane(static_cast<Eigen::Index>(ring.size()), 2);
  for (size_t k = 0; k < ring.size(); ++k) {
    const Eigen::Vector3d p = mesh.vertices.row(ring[k]).transpose() - point;
    in_plane.row(static_cast<Eigen::Index>(k)) << p.dot(u), p.dot(w);
  }
  out.polygon_girth_mm = ConvexHullPerimeter(in_plane);
  return out;
}

// Names each girth's datum point (catalogue names; "" when the level is
// given by its plane only, e.g. the ankle girth's minimum).
std::string GirthLandmark(const std::string& measurement, const std::string& side) {
  static const std::map<std::string, std::string> torso = {
      {"neck_girth", "back_neck"},    {"chest_girth", "axilla_front_right"},
      {"bust_girth", "bust_right"},   {"under_bust_girth", "under_bust"},
      {"waist_girth", "front_waist"}, {"middle_hip_girth", "middle_hip_front"},
      {"hip_girth", "hip_back"}};
  static const std::map<std::string, std::string> limb = {
      {"upper_arm_girth", "upper_arm"}, {"elbow_girth", "elbow"}, {"wrist_girth", "wrist"},
      {"thigh_girth", "thigh"},         {"knee_girth", "knee"},   {"calf_girth", "calf"}};
  if (side.empty()) return torso.count(measurement) ? torso.at(measurement) : "";
  return limb.count(measurement) ? limb.at(measurement) + "_" + side : "";
}

// The joint centres (ParametricBodyDetails::joints): the spine from the
// torso sections, the limbs' from the build, the left side mirrored.
std::map<std::string, Eigen::Vector3d> Skeleton(const Build& b) {
  const BodyLayout& L = *b.layout;
  std::map<std::string, Eigen::Vector3d> joints = b.joints;
  for (const auto& [name, z] : {std::pair{"pelvis", L.z_hip}, std::pair{"spine-4", L.z_waist},
                                std::pair{"spine-3", L.z_under_bust},
                                std::pair{"spine-2", L.z_bust}, std::pair{"spine-1", L.z_armpit},
                                std::pair{"neck", L.z_back_neck}, std::pair{"head", L.z_chin}}) {
    const Section s = InterpolateSection(L.torso, z);
    joints[name] = Eigen::Vector3d(s.cu, s.cv, z);
  }
  for (const auto& [name, p] : b.joints)
    if (name.rfind("r-", 0) == 0)
      joints["l-" + name.substr(2)] = Eigen::Vector3d(-p.x(), p.y(), p.z());
  return joints;
}

}  // namespace

Body GenerateParametricBody(const ParametricBodyOptions& options, ParametricBodyDetails* details) {
  const BodyLayout layout = MakeLayout(options);
  Build b;
  b.layout = &layout;
  b.n = layout.options.torso_segments;
  parametric::BuildTorso(&b);
  parametric::BuildLegs(&b);
  parametric::BuildArms(&b);
  AddTorsoLandmarksAndGirths(&b);
  std::vector<BodyPart> part(static_cast<size_t>(b.mesh.num_vertices()), BodyPart::kTorso);
  for (size_t k = 0; k < b.part_starts.size(); ++k) {
    const int end =
        k + 1 < b.part_starts.size() ? b.part_starts[k + 1].first : b.mesh.num_vertices();
    for (int v = b.part_starts[k].first; v < end; ++v)
      part[static_cast<size_t>(v)] = b.part_starts[k].second;
  }
  const std::vector<std::vector<int>> girth_rings_before = [&] {
    std::vector<std::vector<int>> r;
    for (const auto& g : b.girths) r.push_back(g.ring);
    return r;
  }();
  parametric::RefineGirthRings(&b, layout.options.girth_ring_segments);
  part.resize(static_cast<size_t>(b.mesh.num_vertices()), BodyPart::kTorso);
  for (size_t k = 0; k < b.girths.size(); ++k) {  // new ring vertices take their ring's part
    const BodyPart p = part[static_cast<size_t>(girth_rings_before[k][0])];
    for (int v : b.girths[k].ring) {
      part[static_cast<size_t>(v)] = p;
      if (b.girths[k].limb)
        part[static_cast<size_t>(b.Mirror(v))] = p == BodyPart::kArmRight   ? BodyPart::kArmLeft
                                                 : p == BodyPart::kLegRight ? BodyPart::kLegLeft
                                                                            : p;
    }
  }
  parametric::CarveCleavage(part, &b);

  Body body;
  body.model = "parametric";
  body.mesh = b.mesh.Build();
  const MeshTopology topology = AnalyzeTopology(body.mesh);
  if (!topology.IsClosedSphere()) {
    throw InternalError("parametric body: the mesh is not a closed oriented sphere: " +
                        topology.Describe());
  }
  std::vector<int> face_of(static_cast<size_t>(body.mesh.num_vertices()), -1);
  for (int f = 0; f < body.mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) face_of[static_cast<size_t>(body.mesh.faces(f, c))] = f;
  }
  for (const auto& [name, vertex] : b.landmarks) {
    body.landmarks[name] = AtVertex(body.mesh, face_of, vertex);
    const std::string left = LeftName(name);
    if (!left.empty()) body.landmarks[left] = AtVertex(body.mesh, face_of, b.Mirror(vertex));
  }
  // The bust points: the ends of the bust section's flat front, where the
  // skin rising out of the cleavage (CarveCleavage) meets the tape's line;
  // the exact points, on the ring's edges.
  const Section bust = InterpolateSection(layout.torso, layout.z_bust);
  for (const double sign : {1.0, -1.0}) {
    const Eigen::Vector3d apex(bust.cu + sign * bust.front.w, bust.cv + bust.front.b,
                               layout.z_bust);
    body.landmarks[sign > 0 ? "bust_right" : "bust_left"] = ClosestSurfacePoint(body.mesh, apex);
  }
  body.parameters = layout.options.ToMap();
  for (const auto& [name, value] : b.derived) body.parameters[name] = value;
  std::vector<AnalyticGirth> all;
  for (const parametric::GirthRing& g : b.girths) {
    if (!g.limb) {
      all.push_back(MakeGirth(g, body.mesh, "", g.ring, g.plane_point, g.plane_normal));
      continue;
    }
    all.push_back(MakeGirth(g, body.mesh, "right", g.ring, g.plane_point, g.plane_normal));
    std::vector<int> left;
    for (auto it = g.ring.rbegin(); it != g.ring.rend(); ++it) left.push_back(b.Mirror(*it));
    const Eigen::Vector3d flip(-1, 1, 1);
    all.push_back(MakeGirth(g, body.mesh, "left", left, g.plane_point.cwiseProduct(flip),
                            g.plane_normal.cwiseProduct(flip)));
  }
  for (AnalyticGirth& g : all) {
    g.landmark = GirthLandmark(g.measurement, g.side);
    const double deficit = g.girth_mm - g.polygon_girth_mm;
    if (deficit < -1e-6 || deficit > layout.options.max_girth_deficit_mm) {
      throw InternalError(
          "parametric body: " + g.measurement + " ring polygon is " + std::to_string(deficit) +
          " mm shorter than the analytic girth (allowed 0-" +
          std::to_string(layout.options.max_girth_deficit_mm) + "); use more segments");
    }
    const std::string key = g.measurement + (g.side.empty() ? "" : "_" + g.side) + "_analytic_mm";
    body.parameters[key] = g.girth_mm;
  }
  if (details) {
    details->joints = Skeleton(b);
    details->girths = std::move(all);
    details->part = std::move(part);
  }
  return body;
}

}  // namespace bespoke
