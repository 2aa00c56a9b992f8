#include "tests/support/corpus.h"

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <random>

#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/scan_sim.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/types.h"
#include "scanners/io/scan_io.h"

namespace bespoke::testing {
namespace fs = std::filesystem;

void WriteSyntheticBodyScan(const SyntheticScanOptions& o, const fs::path& file) {
  // A parametric body (oracle/body) scanned by the virtual booth
  // (oracle/scan_sim): a person the landmark detector and the measuring
  // can work on (a bundle of cylinders is not one).
  ParametricBodyOptions shape;
  const double g = o.girth_scale;
  // Lengths follow the stature (the default body's proportions), so a tall
  // subject keeps a plausible crotch height / stature ratio (Check() allows
  // 0.40-0.50: a 1920 mm person with the default 760 mm crotch is rejected).
  const double length_scale = o.stature_mm / shape.stature_mm;
  shape.stature_mm = o.stature_mm;
  for (double* length : {&shape.crotch_height_mm, &shape.arm_length_mm, &shape.stance_width_mm})
    *length *= length_scale;
  // The shoulder width is bounded by both the stature (0.18-0.30) and the chest
  // girth / pi (1.0-1.6): the geometric mean of the two scales keeps it inside
  // both for every stature and girth scale make_corpus draws.
  shape.shoulder_width_mm *= std::sqrt(length_scale * o.girth_scale);
  for (double* girth :
       {&shape.neck_girth_mm, &shape.chest_girth_mm, &shape.bust_girth_mm,
        &shape.under_bust_girth_mm, &shape.waist_girth_mm, &shape.middle_hip_girth_mm,
        &shape.hip_girth_mm, &shape.upper_arm_girth_mm, &shape.wrist_girth_mm,
        &shape.thigh_girth_mm, &shape.knee_girth_mm, &shape.calf_girth_mm, &shape.ankle_girth_mm})
    *girth *= g;
  shape.torso_segments = 48;  // a coarse mesh: quick to build, the scan is what matters
  shape.arm_segments = 32;
  shape.ring_spacing_mm = 20;
  shape.girth_ring_segments = 64;
  shape.max_girth_deficit_mm = 2.0;
  const Body body = GenerateParametricBody(shape);
  ScanSimOptions booth;
  // About `points` body points: the booth's rays scale with width x height.
  const double scale = std::sqrt(std::max(1000, o.points) / 200000.0);
  booth.booth.width_px = std::max(40, static_cast<int>(std::lround(200 * scale)));
  booth.booth.height_px = std::max(30, static_cast<int>(std::lround(150 * scale)));
  booth.noise_sigma_mm = o.noise_mm;
  booth.seed = o.seed;
  ScanSimResult scan = SimulateScan(booth, body.mesh);
  const Eigen::Affine3d scanner_from_body(
      Eigen::AngleAxisd(o.yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
  TransformInPlace(scanner_from_body, &scan.cloud);
  scan.cloud.points /= 1000.0;  // written in metres, as most scanners do
  scan.cloud.normals.resize(0, 3);
  scan.cloud.scalars.clear();
  WriteScan({}, scan.cloud, file);
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
  const std::string xyz_header =
      "property float x\nproperty float y\nproperty float z\nend_header\n";
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
  std::string lies =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3000\n"
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
