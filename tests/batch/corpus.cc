#include "tests/batch/corpus.h"

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <random>

#include "scanners/core/atomic_file.h"
#include "scanners/core/types.h"
#include "scanners/io/scan_io.h"

namespace bespoke::testing {
namespace fs = std::filesystem;

namespace {

// A point on an elliptic cylinder between heights z0 and z1 around (cx, cy).
Eigen::Vector3d OnCylinder(std::mt19937& rng, double cx, double cy, double rx, double ry,
                           double z0, double z1, double tilt_x = 0) {
  std::uniform_real_distribution<double> u(0, 1);
  const double a = 2 * M_PI * u(rng), t = u(rng);
  const double z = z0 + t * (z1 - z0);
  return {cx + rx * std::cos(a) + tilt_x * (z1 - z), cy + ry * std::sin(a), z};
}

}  // namespace

void WriteSyntheticBodyScan(const SyntheticScanOptions& o, const fs::path& file) {
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> noise(0, o.noise_mm);
  const double h = o.stature_mm / 1750.0, g = o.girth_scale;
  const int floor_points = o.points / 10;
  PointCloud cloud;
  cloud.points.resize(o.points + floor_points, 3);
  for (int i = 0; i < o.points; ++i) {
    const double part = u(rng);
    Eigen::Vector3d p;
    if (part < 0.40) {
      p = OnCylinder(rng, 0, 0, 160 * g, 110 * g, 820 * h, 1450 * h);  // torso
    } else if (part < 0.70) {
      p = OnCylinder(rng, part < 0.55 ? 95 * g : -95 * g, 0, 65 * g, 65 * g, 0, 820 * h);  // legs
    } else if (part < 0.88) {
      const double side = part < 0.79 ? 1 : -1;  // arms, A-pose
      p = OnCylinder(rng, side * 215 * g, 0, 40 * g, 40 * g, 800 * h, 1420 * h, side * 0.25);
    } else if (part < 0.92) {
      p = OnCylinder(rng, 0, 0, 55 * g, 55 * g, 1450 * h, 1550 * h);  // neck
    } else {
      const double a = 2 * M_PI * u(rng), c = 2 * u(rng) - 1, s = std::sqrt(1 - c * c);
      p = {90 * g * s * std::cos(a), 100 * g * s * std::sin(a), 1650 * h + 100 * h * c};  // head
    }
    cloud.points.row(i) = (p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng))).transpose();
  }
  for (int i = 0; i < floor_points; ++i) {
    cloud.points.row(o.points + i) << 1200 * u(rng) - 600, 1200 * u(rng) - 600, noise(rng);
  }
  const Eigen::Affine3d scanner_from_body(
      Eigen::AngleAxisd(o.yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
  TransformInPlace(scanner_from_body, &cloud);
  cloud.points /= 1000.0;  // written in metres, as most scanners do
  WriteScan({}, cloud, file);
}

std::vector<std::string> WriteHostileFiles(const fs::path& dir, std::uint32_t seed) {
  CreateDirectories(dir);
  std::vector<std::string> names;
  auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    names.push_back(name);
  };
  // truncated.ply: a good scan cut at 60 %.
  const fs::path good = dir / ".truncated-source.ply";  // hidden: not discovered
  WriteSyntheticBodyScan({20000, 1700, 1.0, 1.0, 0, seed}, good);
  {
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    write("truncated.ply", bytes.substr(0, bytes.size() * 6 / 10));
  }
  fs::remove(good);
  const std::string xyz_header = "property float x\nproperty float y\nproperty float z\nend_header\n";
  write("huge_count.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n" +
                              xyz_header + std::string(24, '\0'));
  std::string nans = "ply\nformat ascii 1.0\nelement vertex 5000\n" + xyz_header;
  for (int i = 0; i < 5000; ++i) nans += "nan nan nan\n";
  write("all_nan.ply", nans);
  write("zero_points.ply", "ply\nformat ascii 1.0\nelement vertex 0\n" + xyz_header);
  write("empty.xyz", "");
  std::mt19937 rng(seed);
  std::string garbage(4096, '\0');
  for (char& c : garbage) c = static_cast<char>(rng() & 0xff);
  write("garbage.pcd", garbage);
  std::string lies = "ply\nformat binary_little_endian 1.0\nelement vertex 3000\n"
                     "property double x\nproperty double y\nproperty double z\nend_header\n";
  write("header_lies.ply", lies + std::string(3000 * 12, '\x01'));
  fs::create_directories(dir / "folder.ply");
  names.push_back("folder.ply");
  ::mkfifo((dir / "fifo.ply").c_str(), 0644);
  names.push_back("fifo.ply");
  fs::create_symlink(dir / "no-such-scan.ply.missing", dir / "dangling.ply");
  names.push_back("dangling.ply");
  return names;
}

}  // namespace bespoke::testing
