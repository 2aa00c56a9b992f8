#include "measure/measurements/section_girth.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "measure/measurements/section_holes.h"
#include "measure/tape/convex_hull_2d.h"
#include "scanners/core/cell_key.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
constexpr int kBins = 180;  // 2-degree angular bins around a loop's centre
constexpr double kTwoPi = 6.283185307179586;

struct PlaneFrame {
  Vec3 origin, u, v;
  Vec2 To2d(const Vec3& x) const { return {(x - origin).dot(u), (x - origin).dot(v)}; }
  Vec3 To3d(const Vec2& p) const { return origin + p.x() * u + p.y() * v; }
};

PlaneFrame MakeFrame(const Vec3& point, const Vec3& normal) {
  const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = normal.cross(helper).normalized();
  return {point, u, normal.cross(u)};
}

// Union-find over the slab points, linking pairs closer than `gap` (grid hash).
std::vector<int> Cluster(const std::vector<Vec2>& p, double gap, int* count) {
  std::vector<int> parent(p.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto key = [](long long x, long long y) { return CellKey2(x, y); };
  std::unordered_map<long long, std::vector<int>> cells;
  for (std::size_t i = 0; i < p.size(); ++i)
    cells[key(std::llround(std::floor(p[i].x() / gap)), std::llround(std::floor(p[i].y() / gap)))]
        .push_back(static_cast<int>(i));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const long long cx = std::llround(std::floor(p[i].x() / gap)),
                    cy = std::llround(std::floor(p[i].y() / gap));
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(key(cx + dx, cy + dy));
        if (it == cells.end()) continue;
        for (int j : it->second)
          if ((p[i] - p[j]).squaredNorm() <= gap * gap) parent[find(static_cast<int>(i))] = find(j);
      }
  }
  std::vector<int> label(p.size(), -1), remap(p.size(), -1);
  *count = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int root = find(static_cast<int>(i));
    if (remap[root] < 0) remap[root] = (*count)++;
    label[i] = remap[root];
  }
  return label;
}

Eigen::MatrixX2d ToMatrix(const std::vector<Vec2>& p) {
  Eigen::MatrixX2d m(static_cast<Eigen::Index>(p.size()), 2);
  for (std::size_t i = 0; i < p.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = p[i].transpose();
  return m;
}

bool HullContains(const std::vector<Vec2>& pts, const Vec2& q) {
  if (pts.size() < 3) return false;
  const Eigen::MatrixX2d m = ToMatrix(pts);
  const std::vector<int> hull = ConvexHullIndices(m);
  if (hull.size() < 3) return false;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 a = m.row(hull[i]).transpose(), b = m.row(hull[(i + 1) % hull.size()]).transpose();
    const Vec2 e = b - a, w = q - a;
    if (e.x() * w.y() - e.y() * w.x() < 0) return false;  // hull is counter-clockwise
  }
  return true;
}

double MinDistance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& x : a)
    for (const Vec2& y : b) best = std::min(best, (x - y).squaredNorm());
  return std::sqrt(best);
}

Vec2 Mean(const std::vector<Vec2>& p) {
  Vec2 m = Vec2::Zero();
  for (const Vec2& x : p) m += x;
  return p.empty() ? m : Vec2(m / static_cast<double>(p.size()));
}

int BinOf(const Vec2& d) {
  const double a = std::atan2(d.y(), d.x()) + kTwoPi / 2;  // 0..2pi
  return std::min(kBins - 1, static_cast<int>(a / kTwoPi * kBins));
}

// Widest empty angular gap (degrees) of `p` seen from its own centroid: an
// arc of a loop leaves >= ~180 degrees empty, a closed loop (a hand) little.
double OwnAngularGapDeg(const std::vector<Vec2>& p) {
  const Vec2 c = Mean(p);
  std::vector<bool> hit(kBins, false);
  for (const Vec2& x : p) hit[BinOf(x - c)] = true;
  int best = 0, run = 0;
  for (int k = 0; k < 2 * kBins; ++k)
    run = hit[k % kBins] ? 0 : run + 1, best = std::max(best, std::min(run, kBins));
  return best * 360.0 / kBins;
}

// The centre to see the part's loop from: its centroid when the part goes
// round (its own angular gap under 120 degrees); for an arc, the centroid
// lies near the arc, so the centre of the circle fitted to it (algebraic
// least squares: x^2 + y^2 + D x + E y + F = 0), unless the fit is
// degenerate or its radius exceeds the arc's own extent (a flat piece).
Vec2 LoopCentre(const std::vector<Vec2>& p) {
  const Vec2 mean = Mean(p);
  if (p.size() < 3 || OwnAngularGapDeg(p) < 120) return mean;
  Eigen::MatrixX3d a(static_cast<Eigen::Index>(p.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(p.size()));
  double extent = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 d = p[i] - mean;  // centred for conditioning
    a.row(static_cast<Eigen::Index>(i)) << d.x(), d.y(), 1;
    b(static_cast<Eigen::Index>(i)) = -d.squaredNorm();
    extent = std::max(extent, d.norm());
  }
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
  const Vec2 centre(-def(0) / 2, -def(1) / 2);
  const double r2 = centre.squaredNorm() - def(2);
  if (!centre.allFinite() || !(r2 > 0) || std::sqrt(r2) > 2 * extent) return mean;
  return mean + centre;
}

// Angular occupancy of the part around `centre`: per bin, point count and mean radius.
struct Occupancy {
  std::vector<int> count = std::vector<int>(kBins, 0);
  std::vector<double> radius = std::vector<double>(kBins, 0.0);
};

Occupancy Occupy(const std::vector<Vec2>& p, const Vec2& centre) {
  Occupancy o;
  for (const Vec2& x : p) {
    const int b = BinOf(x - centre);
    o.radius[b] += (x - centre).norm(), ++o.count[b];
  }
  for (int b = 0; b < kBins; ++b)
    if (o.count[b]) o.radius[b] /= o.count[b];
  return o;
}

// True when `piece` continues the part's loop across a hole: it lies mostly
// in the part's empty bins, and at both ends its radius matches the radius
// of the part's nearest occupied bins.
bool ContinuesLoop(const SectionGirthOptions& options, const std::vector<Vec2>& piece,
                   const Occupancy& part, const Vec2& centre) {
  const Occupancy own = Occupy(piece, centre);
  int inside = 0, total = 0;
  for (int b = 0; b < kBins; ++b) {
    if (!own.count[b]) continue;
    total += own.count[b];
    if (part.count[b] || part.count[(b + 1) % kBins] || part.count[(b + kBins - 1) % kBins])
      inside += own.count[b];
  }
  if (inside > 0.2 * total) return false;
  // The piece's angular extent: the complement of its widest empty run.
  int best = -1, best_end = 0, run = 0;
  for (int k = 0; k < 2 * kBins; ++k) {
    run = own.count[k % kBins] ? 0 : run + 1;
    if (run > best && run <= kBins) best = run, best_end = k;
  }
  const int first = (best_end + 1) % kBins;  // first occupied bin after the gap
  int last = first;
  for (int k = 0; k < kBins; ++k)
    if (own.count[(first + k) % kBins]) last = (first + k) % kBins;
  auto neighbour = [&](int from, int step) {
    for (int k = 1; k < kBins; ++k) {
      const int b = ((from + step * k) % kBins + kBins) % kBins;
      if (part.count[b]) return b;
    }
    return -1;
  };
  const int before = neighbour(first, -1), after = neighbour(last, +1);
  if (before < 0 || after < 0) return false;
  auto matches = [&](double r, double expected) {
    return std::abs(r - expected) <= options.radius_tolerance * expected;
  };
  return matches(own.radius[first], part.radius[before]) &&
         matches(own.radius[last], part.radius[after]);
}

// The mean point of each angular bin of about smooth_arc_mm of arc.
std::vector<Vec2> Denoise(const std::vector<Vec2>& p, const Vec2& centre, double arc_mm) {
  double r = 0;
  for (const Vec2& x : p) r += (x - centre).norm();
  r /= static_cast<double>(p.size());
  const int bins = std::max(8, static_cast<int>(kTwoPi * r / arc_mm));
  std::vector<Vec2> sum(static_cast<std::size_t>(bins), Vec2::Zero());
  std::vector<int> n(static_cast<std::size_t>(bins), 0);
  for (const Vec2& x : p) {
    const Vec2 d = x - centre;
    const double a = std::atan2(d.y(), d.x()) + kTwoPi / 2;
    const auto b =
        static_cast<std::size_t>(std::min(bins - 1, static_cast<int>(a / kTwoPi * bins)));
    sum[b] += x, ++n[b];
  }
  std::vector<Vec2> out;
  for (std::size_t b = 0; b < sum.size(); ++b)
    if (n[b]) out.push_back(sum[b] / n[b]);
  return out;
}

double LargestGap(const std::vector<Vec2>& p, const Vec2& centre) {
  if (p.size() < 2) return 0;
  std::vector<std::pair<double, int>> order;
  for (std::size_t i = 0; i < p.size(); ++i)
    order.emplace_back(std::atan2(p[i].y() - centre.y(), p[i].x() - centre.x()),
                       static_cast<int>(i));
  std::sort(order.begin(), order.end());
  double gap = 0;
  for (std::size_t i = 0; i < order.size(); ++i)
    gap = std::max(gap, (p[order[i].second] - p[order[(i + 1) % order.size()].second]).norm());
  return gap;
}

// The distance (mm) between the two points of `p` angularly either side of
// `q`, seen from `centre`: the width of the hole `q` lies in, or the
// spacing of the loop where it is whole.
double GapAround(const std::vector<Vec2>& p, const Vec2& centre, const Vec2& q) {
  const double at = std::atan2(q.y() - centre.y(), q.x() - centre.x());
  double before = -kTwoPi, after = kTwoPi;  // angular offsets from q, wrapped to (-pi, pi]
  Vec2 a = q, b = q;
  for (const Vec2& x : p) {
    double d = std::atan2(x.y() - centre.y(), x.x() - centre.x()) - at;
    d = std::remainder(d, kTwoPi);
    if (d <= 0 && d > before) before = d, a = x;
    if (d > 0 && d < after) after = d, b = x;
  }
  return (a - b).norm();
}

struct GapPoint {
  Vec2 at, normal;  // on the plane (mm); the normal's component in it
};

// Step 1: the slab's points on the plane (2-D), those of members.gap_only
// into `reserve` with their normals on the plane (2-D, zero without
// normals), those left out dropped.
void SlabPoints(const SectionGirthOptions& options, const Eigen::MatrixX3d& cloud,
                const Eigen::MatrixX3d& normals, const PlaneFrame& frame, const Vec3& plane_normal,
                const SectionMembers& members, std::vector<Vec2>* slab,
                std::vector<GapPoint>* reserve) {
  const Eigen::VectorXd offset = (cloud.rowwise() - frame.origin.transpose()) * plane_normal;
  for (Eigen::Index i = 0; i < cloud.rows(); ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (!(std::abs(offset(i)) <= options.half_thickness_mm)) continue;
    if (!members.leave_out.empty() && members.leave_out[k]) continue;
    Vec3 x = cloud.row(i).transpose();
    if (normals.rows()) {
      // Slide along the surface (its tangent closest to the plane normal)
      // onto the plane: t = n - (n.s)s, moving by -offset / |t|^2 * t makes
      // the offset 0. Points needing a longer slide than max_slide_mm lie
      // where the surface is nearly parallel to the plane, off the section.
      const Vec3 s = normals.row(i).transpose();
      const Vec3 t = plane_normal - plane_normal.dot(s) * s;
      const double slide = std::abs(offset(i)) / std::max(1e-9, t.norm());
      if (!(slide <= options.max_slide_mm)) continue;  // nearly parallel: far from the section
      x -= offset(i) / t.squaredNorm() * t;
    }
    if (members.gap_only.empty() || !members.gap_only[k]) {
      slab->push_back(frame.To2d(x));
      continue;
    }
    const Vec3 s = normals.rows() ? Vec3(normals.row(i).transpose()) : Vec3::Zero();
    reserve->push_back({frame.To2d(x), Vec2(s.dot(frame.u), s.dot(frame.v))});
  }
}

// Step 4: the points of `reserve` that continue the part's loop across its
// angular gap, seen from LoopCentre: in a bin the part leaves empty (one bin
// of margin), at the radius interpolated by angle between the part's nearest
// occupied bins either side, within radius_tolerance of it. Returns how many
// joined `part`.
int JoinGapPoints(const SectionGirthOptions& options, const std::vector<GapPoint>& reserve,
                  std::vector<Vec2>* part) {
  if (reserve.empty() || part->size() < 3) return 0;
  const Vec2 centre = LoopCentre(*part);
  const Occupancy o = Occupy(*part, centre);
  auto occupied = [&](int b) { return o.count[((b % kBins) + kBins) % kBins] > 0; };
  auto nearest = [&](int from, int step, int* steps) {
    for (*steps = 1; *steps < kBins; ++*steps)
      if (occupied(from + step * *steps)) return ((from + step * *steps) % kBins + kBins) % kBins;
    return -1;
  };
  std::vector<Vec2> joined;
  const double min_cos = std::cos(options.gap_normal_max_deg * kTwoPi / 360);
  for (const auto& [x, normal] : reserve) {
    const double norm = normal.norm();  // short: the skin lies nearly in the plane, no cue
    if (norm > 0.3 && normal.dot(x - centre) < min_cos * norm * (x - centre).norm()) continue;
    const int b = BinOf(x - centre);
    if (occupied(b) || occupied(b - 1) || occupied(b + 1)) continue;
    int back = 0, ahead = 0;
    const int before = nearest(b, -1, &back), after = nearest(b, +1, &ahead);
    if (before < 0 || after < 0) continue;
    const double expected =
        o.radius[before] + (o.radius[after] - o.radius[before]) * back / (back + ahead);
    if (std::abs((x - centre).norm() - expected) <= options.radius_tolerance * expected)
      joined.push_back(x);
  }
  part->insert(part->end(), joined.begin(), joined.end());
  return static_cast<int>(joined.size());
}

}  // namespace

void SectionGirthOptions::Check() const {
  if (!(half_thickness_mm > 0 && half_thickness_mm <= 50))
    throw InputError("section girth: half_thickness_mm must be in (0, 50]");
  if (!(piece_gap_mm > 0) || !(bridge_gap_mm >= piece_gap_mm))
    throw InputError("section girth: need 0 < piece_gap_mm <= bridge_gap_mm");
  if (!(radius_tolerance > 0 && radius_tolerance < 1))
    throw InputError("section girth: radius_tolerance must be in (0, 1)");
  if (!(gap_normal_max_deg > 0 && gap_normal_max_deg <= 180))
    throw InputError("section girth: gap_normal_max_deg must be in (0, 180]");
  if (!(open_gap_mm > 0)) throw InputError("section girth: open_gap_mm must be > 0");
  if (!(max_slide_mm > 0)) throw InputError("section girth: max_slide_mm must be > 0");
  if (!(smooth_arc_mm >= 0)) throw InputError("section girth: smooth_arc_mm must be >= 0");
  if (min_piece_points < 1) throw InputError("section girth: min_piece_points must be >= 1");
  if (!(points_per_gap >= 0)) throw InputError("section girth: points_per_gap must be >= 0");
  if (!(gap_per_spacing >= 0)) throw InputError("section girth: gap_per_spacing must be >= 0");
  if (!(max_half_thickness_mm >= half_thickness_mm && max_half_thickness_mm <= 50))
    throw InputError("section girth: max_half_thickness_mm must be in [half_thickness_mm, 50]");
}

SectionGirthOptions SlabForSpacing(const SectionGirthOptions& options, double surface_spacing_mm) {
  options.Check();
  SectionGirthOptions out = options;
  if (!(surface_spacing_mm > 0) || !std::isfinite(surface_spacing_mm)) return out;
  out.piece_gap_mm = std::max(options.piece_gap_mm, options.gap_per_spacing * surface_spacing_mm);
  out.bridge_gap_mm = std::max(options.bridge_gap_mm, out.piece_gap_mm);
  const double needed =
      options.points_per_gap * surface_spacing_mm * surface_spacing_mm / (2 * out.piece_gap_mm);
  out.half_thickness_mm =
      std::clamp(needed, options.half_thickness_mm, options.max_half_thickness_mm);
  out.max_slide_mm = options.max_slide_mm * out.half_thickness_mm / options.half_thickness_mm;
  return out;
}

SectionGirth MeasureSectionGirth(const SectionGirthOptions& options, const Eigen::MatrixX3d& cloud,
                                 const Eigen::MatrixX3d& normals,
                                 const Eigen::Vector3d& plane_point,
                                 const Eigen::Vector3d& plane_normal,
                                 const Eigen::MatrixX3d& anchors, const SectionMembers& members) {
  options.Check();
  if (std::abs(plane_normal.norm() - 1) > 1e-6 || !plane_point.allFinite())
    throw InputError("section girth: the plane needs a finite point and a unit normal");
  if (anchors.rows() < 1) throw InputError("section girth: at least one anchor point is needed");
  const PlaneFrame frame = MakeFrame(plane_point, plane_normal);
  if (normals.rows() != 0 && normals.rows() != cloud.rows())
    throw InputError("section girth: normals must have one row per point, or none");
  for (const std::vector<bool>* flags : {&members.leave_out, &members.gap_only})
    if (!flags->empty() && flags->size() != static_cast<std::size_t>(cloud.rows()))
      throw InputError("section girth: member flags must have one per point, or none");
  if (!members.tape_points.allFinite())
    throw InputError("section girth: tape points must be finite");
  std::vector<Vec2> slab;
  std::vector<GapPoint> reserve;
  SlabPoints(options, cloud, normals, frame, plane_normal, members, &slab, &reserve);
  SectionGirth out;
  out.points = static_cast<Eigen::Index>(slab.size());
  if (slab.empty()) return out;

  std::vector<int> label = Cluster(slab, options.piece_gap_mm, &out.pieces);
  std::vector<std::vector<Vec2>> pieces(static_cast<std::size_t>(out.pieces));
  for (std::size_t i = 0; i < slab.size(); ++i)
    pieces[static_cast<std::size_t>(label[i])].push_back(slab[i]);
  std::size_t largest = 0;
  for (const auto& piece : pieces) largest = std::max(largest, piece.size());
  auto usable = [&](const std::vector<Vec2>& piece) {
    return piece.size() >=
           std::min<std::size_t>(static_cast<std::size_t>(options.min_piece_points), largest);
  };

  // The seed piece.
  int seed = -1;
  Vec2 centroid = Vec2::Zero();
  for (Eigen::Index a = 0; a < anchors.rows(); ++a)
    centroid += frame.To2d(anchors.row(a).transpose());
  centroid /= static_cast<double>(anchors.rows());
  if (anchors.rows() > 1)
    for (std::size_t k = 0; k < pieces.size() && seed < 0; ++k)
      if (usable(pieces[k]) && HullContains(pieces[k], centroid)) seed = static_cast<int>(k);
  out.anchor_enclosed = seed >= 0;
  if (seed < 0) {
    const std::vector<Vec2> anchor0 = {frame.To2d(anchors.row(0).transpose())};
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (!usable(pieces[k])) continue;
      const double d = MinDistance(pieces[k], anchor0);
      if (d < best) best = d, seed = static_cast<int>(k);
    }
  }
  std::vector<Vec2> part = pieces[static_cast<std::size_t>(seed)];
  std::vector<bool> taken(pieces.size(), false);
  taken[static_cast<std::size_t>(seed)] = true;

  // The limbs left out, every piece left is the part's.
  for (std::size_t k = 0; members.one_part && k < pieces.size(); ++k) {
    if (taken[k] || pieces[k].size() < static_cast<std::size_t>(options.min_piece_points)) continue;
    taken[k] = true;
    part.insert(part.end(), pieces[k].begin(), pieces[k].end());
    ++out.pieces_joined;
  }
  // Arcs of the same loop across scan holes: the nearest piece that
  // continues the part's loop seen from its centroid, else, when the part is
  // itself an arc, from the centre of the circle fitted to it.
  auto pick_arc = [&](const Vec2& centre) {
    const Occupancy occupancy = Occupy(part, centre);
    int pick = -1;
    double pick_distance = options.bridge_gap_mm;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (taken[k] || !usable(pieces[k])) continue;
      const double d = MinDistance(pieces[k], part);
      if (d > pick_distance) continue;
      if (OwnAngularGapDeg(pieces[k]) < 120) continue;  // a closed loop of its own
      if (!ContinuesLoop(options, pieces[k], occupancy, centre)) continue;
      pick = static_cast<int>(k), pick_distance = d;
    }
    return pick;
  };
  for (bool grew = !members.one_part; grew;) {
    grew = false;
    const Vec2 mean = Mean(part);
    int pick = pick_arc(mean);
    if (pick < 0) {
      const Vec2 fitted = LoopCentre(part);
      if (fitted != mean) pick = pick_arc(fitted);
    }
    if (pick >= 0) {
      taken[static_cast<std::size_t>(pick)] = true;
      part.insert(part.end(), pieces[static_cast<std::size_t>(pick)].begin(),
                  pieces[static_cast<std::size_t>(pick)].end());
      ++out.pieces_joined;
      grew = true;
    }
  }

  out.gap_points_joined = JoinGapPoints(options, reserve, &part);
  const Vec2 centre = Mean(part);
  out.largest_gap_mm = LargestGap(part, centre);
  out.open = out.largest_gap_mm > options.open_gap_mm;
  std::vector<Vec2> outline =
      options.smooth_arc_mm > 0 ? Denoise(part, centre, options.smooth_arc_mm) : part;
  if (members.skin_over_holes && out.open) {
    SkinOverHolesOptions holes;
    holes.open_gap_mm = options.open_gap_mm;
    const SkinOverHoles fill = FillSectionHoles(holes, ToMatrix(part));
    for (Eigen::Index k = 0; k < fill.points.rows(); ++k)
      outline.push_back(fill.points.row(k).transpose());
    out.bridged_mm = fill.bridged_mm;
  }
  for (Eigen::Index t = 0; t < members.tape_points.rows(); ++t) {
    const Vec2 q = frame.To2d(members.tape_points.row(t).transpose());
    if (GapAround(part, centre, q) > options.open_gap_mm) outline.push_back(q);
  }
  const Eigen::MatrixX2d m = ToMatrix(outline);
  const std::vector<int> hull = ConvexHullIndices(m);
  out.hull.resize(static_cast<Eigen::Index>(hull.size()), 3);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    out.hull.row(static_cast<Eigen::Index>(i)) = frame.To3d(m.row(hull[i]).transpose()).transpose();
    if (hull.size() >= 2)
      out.girth_mm += (m.row(hull[(i + 1) % hull.size()]) - m.row(hull[i])).norm();
  }
  out.part.resize(static_cast<Eigen::Index>(part.size()), 3);
  for (std::size_t i = 0; i < part.size(); ++i)
    out.part.row(static_cast<Eigen::Index>(i)) = frame.To3d(part[i]).transpose();
  return out;
}

}  // namespace bespoke
