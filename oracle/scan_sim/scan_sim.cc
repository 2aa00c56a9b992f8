#include "oracle/scan_sim/scan_sim.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "oracle/scan_sim/raycaster.h"
#include "oracle/scan_sim/scene_objects.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

void CheckScanRange(const char* name, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InputError(std::string("scan-sim: ") + name + " = " + std::to_string(value) +
                     " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
}

// A generator for stream `stream` of the run's seed (sensors, outliers,
// placement and transforms draw from separate streams, so changing one
// option does not reshuffle the others).
std::mt19937_64 Stream(std::uint64_t seed, std::uint64_t stream) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32),
                    0x5ca9u};
  return std::mt19937_64(seq);
}

Eigen::Matrix3d RandomSmallRotation(std::mt19937_64& rng, double sigma_rad) {
  std::normal_distribution<double> normal(0, 1);
  Eigen::Vector3d axis(normal(rng), normal(rng), normal(rng));
  if (axis.norm() == 0) axis = Eigen::Vector3d::UnitZ();
  return Eigen::AngleAxisd(sigma_rad * normal(rng), axis.normalized()).toRotationMatrix();
}

Eigen::Affine3d MakeTransform(ScanTransform kind, std::uint64_t seed) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  if (kind == ScanTransform::kYUp) {
    // y up, the person facing +z, x to the person's left: a common scanner
    // convention (x_s = -x_b, y_s = z_b, z_s = y_b).
    t.linear() << -1, 0, 0, 0, 0, 1, 0, 1, 0;
  } else if (kind == ScanTransform::kRandom) {
    auto rng = Stream(seed, 0x7f);
    std::normal_distribution<double> normal(0, 1);
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));  // uniform on SO(3)
    q.normalize();
    std::uniform_real_distribution<double> offset(-1500, 1500);
    t.linear() = q.toRotationMatrix();
    t.translation() = Eigen::Vector3d(offset(rng), offset(rng), offset(rng));
  }
  return t;
}

struct Collected {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<int> source, sensor;
  void Add(const Eigen::Vector3d& p, const Eigen::Vector3d& n, ScanSource s, int k) {
    points.push_back(p);
    normals.push_back(n);
    source.push_back(static_cast<int>(s));
    sensor.push_back(k);
  }
};

// Outliers: 80 % flying pixels (a recorded return moved along its sensor's
// ray by 30-300 mm, as at depth edges and on dark surfaces), 20 % clutter
// uniform in the booth volume, facing a random sensor.
void AddOutliers(const ScanSimOptions& o, const std::vector<DepthSensor>& sensors, Collected* c) {
  const size_t good = c->points.size();
  if (o.outlier_fraction <= 0 || good == 0) return;
  const auto count =
      static_cast<size_t>(std::llround(o.outlier_fraction / (1 - o.outlier_fraction) * good));
  auto rng = Stream(o.seed, 0x07u);
  std::uniform_int_distribution<size_t> pick(0, good - 1);
  std::uniform_int_distribution<int> pick_sensor(0, static_cast<int>(sensors.size()) - 1);
  std::uniform_real_distribution<double> unit(0, 1);
  const double r = o.booth.radius_mm * 0.8;
  for (size_t i = 0; i < count; ++i) {
    if (i % 5 != 4) {  // four in five: flying pixels
      const size_t j = pick(rng);
      const int k = c->sensor[j];
      const Eigen::Vector3d eye = sensors[static_cast<size_t>(k)].position();
      const Eigen::Vector3d ray = (c->points[j] - eye).normalized();
      const double jump = (unit(rng) < 0.5 ? -1 : 1) * (30 + 270 * unit(rng));
      c->Add(c->points[j] + jump * ray, -ray, ScanSource::kOutlier, k);
    } else {
      const Eigen::Vector3d p(r * (2 * unit(rng) - 1), r * (2 * unit(rng) - 1), 2200 * unit(rng));
      const int k = pick_sensor(rng);
      c->Add(p, (sensors[static_cast<size_t>(k)].position() - p).normalized(), ScanSource::kOutlier,
             k);
    }
  }
}

// One sensor's depth image: cast its rays (from its true, possibly
// misaligned pose), drop grazing and out-of-range returns, add range noise,
// report the points with the calibrated pose. `ids`: body and floor mesh ids.
void ScanWithSensor(const ScanSimOptions& o, const MeshRaycaster& caster, std::pair<int, int> ids,
                    int k, ScanSimResult* result, Collected* c) {
  const DepthSensor& nominal = result->sensors[static_cast<size_t>(k)];
  auto rng = Stream(o.seed, 1000 + static_cast<std::uint64_t>(k));
  // The sensor's true pose: the calibrated one moved by a small rigid error.
  Eigen::Affine3d truth = nominal.body_from_camera;
  if (o.misalign_mm > 0 || o.misalign_deg > 0) {
    std::normal_distribution<double> normal(0, 1);
    Eigen::Affine3d error = Eigen::Affine3d::Identity();
    error.linear() = RandomSmallRotation(rng, o.misalign_deg * kPi / 180);
    error.translation() = o.misalign_mm * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    truth = nominal.body_from_camera * error;
  }
  const Eigen::Affine3d reported_from_true = nominal.body_from_camera * truth.inverse();
  const int n = nominal.width_px * nominal.height_px;
  Eigen::MatrixX3d origins(n, 3), directions(n, 3);
  DepthSensor true_sensor = nominal;
  true_sensor.body_from_camera = truth;
  for (int v = 0, i = 0; v < nominal.height_px; ++v) {
    for (int u = 0; u < nominal.width_px; ++u, ++i) {
      origins.row(i) = truth.translation();
      directions.row(i) = true_sensor.Ray(u, v);
    }
  }
  const RayHits hits = caster.Cast(origins, directions);
  result->rays += n;
  std::normal_distribution<double> noise(0, o.noise_sigma_mm > 0 ? o.noise_sigma_mm : 1.0);
  for (int i = 0; i < n; ++i) {
    if (hits.geometry[i] < 0) continue;
    const Eigen::Vector3d d = directions.row(i);
    const Eigen::Vector3d face_normal = hits.normal.row(i);
    const double cosine = face_normal.dot(d);
    const double range = hits.distance[i];
    const double e =
        o.noise_sigma_mm > 0 ? noise(rng) : 0.0;  // drawn for every hit: stable streams
    if (std::abs(cosine) < o.min_incidence_cos) {
      ++result->dropped_grazing;
      continue;
    }
    if (range < nominal.min_range_mm || range > nominal.max_range_mm) {
      ++result->dropped_range;
      continue;
    }
    const Eigen::Vector3d p = reported_from_true * (truth.translation() + (range + e) * d);
    const Eigen::Vector3d normal =
        reported_from_true.linear() * (cosine > 0 ? -face_normal : face_normal);
    const ScanSource source = hits.geometry[i] == ids.first    ? ScanSource::kBody
                              : hits.geometry[i] == ids.second ? ScanSource::kFloor
                                                               : ScanSource::kStray;
    c->Add(p, normal, source, k);
  }
}

}  // namespace

ScanTransform ParseScanTransform(const std::string& text) {
  if (text == "none") return ScanTransform::kNone;
  if (text == "random") return ScanTransform::kRandom;
  if (text == "y-up") return ScanTransform::kYUp;
  throw InputError("scan-sim: transform must be none, random or y-up, not '" + text + "'");
}

std::string ToString(ScanTransform transform) {
  switch (transform) {
    case ScanTransform::kRandom:
      return "random";
    case ScanTransform::kYUp:
      return "y-up";
    default:
      return "none";
  }
}

void ScanSimOptions::Check() const {
  booth.Check();
  CheckScanRange("noise_sigma_mm", noise_sigma_mm, 0, 50);
  CheckScanRange("outlier_fraction", outlier_fraction, 0, 0.5);
  CheckScanRange("min_incidence_cos", min_incidence_cos, 0, 0.99);
  CheckScanRange("floor_half_size_mm", floor_half_size_mm, 100, 5000);
  CheckScanRange("stray_objects", stray_objects, 0, 8);
  CheckScanRange("misalign_mm", misalign_mm, 0, 100);
  CheckScanRange("misalign_deg", misalign_deg, 0, 10);
}

ScanSimResult SimulateScan(const ScanSimOptions& o, const TriangleMesh& body, Progress* progress) {
  o.Check();
  ScanSimResult result;
  result.sensors = MakeBooth(o.booth);
  MeshRaycaster caster;
  const int body_id = caster.AddMesh(body);
  int floor_id = -1;
  if (o.floor) floor_id = caster.AddMesh(FloorPatch(o.floor_half_size_mm));
  auto placement = Stream(o.seed, 0x57u);
  const std::vector<TriangleMesh> strays =
      PlaceStrayObjects(body, o.stray_objects, o.booth.radius_mm, placement);
  result.stray_objects_placed = static_cast<int>(strays.size());
  for (const TriangleMesh& s : strays) caster.AddMesh(s);

  Collected c;
  ProgressBegin(progress, "scanning", static_cast<std::int64_t>(result.sensors.size()));
  for (size_t k = 0; k < result.sensors.size(); ++k) {
    ScanWithSensor(o, caster, {body_id, floor_id}, static_cast<int>(k), &result, &c);
    ProgressUpdate(progress, static_cast<std::int64_t>(k + 1));
  }
  ProgressEnd(progress);
  AddOutliers(o, result.sensors, &c);

  result.scanner_from_body = MakeTransform(o.transform, o.seed);
  const auto m = static_cast<Eigen::Index>(c.points.size());
  PointCloud& cloud = result.cloud;
  cloud.points.resize(m, 3);
  cloud.normals.resize(m, 3);
  Eigen::VectorXd source(m), sensor(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    cloud.points.row(i) = c.points[static_cast<size_t>(i)];
    cloud.normals.row(i) = c.normals[static_cast<size_t>(i)];
    source[i] = c.source[static_cast<size_t>(i)];
    sensor[i] = c.sensor[static_cast<size_t>(i)];
    ++result.counts[c.source[static_cast<size_t>(i)]];
  }
  cloud.scalars["source"] = source;
  cloud.scalars["sensor"] = sensor;
  TransformInPlace(result.scanner_from_body, &cloud);
  return result;
}

}  // namespace bespoke
