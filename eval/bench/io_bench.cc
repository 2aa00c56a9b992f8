// Reading speed of Bespoke's scan readers against PCL 1.13's own readers on
// the same valid files, in the same process (Google Benchmark).
//
//   build/eval/bench/io_bench [--benchmark_filter=Ply]      (BESPOKE_IO_BENCH_POINTS, default 1e6)
//
// Files: a cloud of N points with normals, colours and one scalar, written by
// Bespoke (PLY: double x y z, float normals, uchar colours, double scalar;
// PCD: all 4-byte floats). PCL reads into pcl::PCLPointCloud2 (its generic,
// conversion-free container); Bespoke reads into PointCloud (doubles) with
// units resolved and NaN points checked, i.e. ReadScan as the pipeline calls
// it. Compare the rows as ratios: absolute times depend on the machine.
#include <benchmark/benchmark.h>
#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

Eigen::Index NumPoints() {
  const char* env = std::getenv("BESPOKE_IO_BENCH_POINTS");
  return env ? std::max<Eigen::Index>(1000, std::atoll(env)) : 1'000'000;
}

PointCloud MakeCloud(Eigen::Index n) {
  PointCloud cloud;
  cloud.points = Eigen::MatrixX3d::Random(n, 3) * 0.9;  // metres
  cloud.points.col(2).array() += 0.9;
  cloud.normals = Eigen::MatrixX3d::Random(n, 3).rowwise().normalized();
  cloud.colors = (Eigen::MatrixX3d::Random(n, 3).array() * 127 + 128).cast<std::uint8_t>();
  cloud.scalars["intensity"] = Eigen::VectorXd::Random(n);
  return cloud;
}

// Writes each benchmark file once (on first use) into a temporary folder.
const std::filesystem::path& File(const std::string& name) {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / "bespoke-io-bench";
    std::filesystem::create_directories(d);
    return d;
  }();
  static std::map<std::string, std::filesystem::path> files;
  auto it = files.find(name);
  if (it != files.end()) return it->second;
  static const PointCloud cloud = MakeCloud(NumPoints());
  WriteOptions options;
  if (name == "ascii.ply") options.ply_encoding = PlyEncoding::kAscii;
  if (name == "be.ply") options.ply_encoding = PlyEncoding::kBinaryBigEndian;
  if (name == "ascii.pcd") options.pcd_encoding = PcdEncoding::kAscii;
  if (name == "compressed.pcd") options.pcd_encoding = PcdEncoding::kBinaryCompressed;
  const auto path = dir / name;
  WriteScan(options, cloud, path);
  return files.emplace(name, path).first->second;
}

void Bespoke(benchmark::State& state, const std::string& name) {
  const auto& file = File(name);
  for (auto _ : state) {
    Scan scan = ReadScan(ReadOptions(), file);
    benchmark::DoNotOptimize(scan.cloud.points.data());
  }
  state.SetItemsProcessed(state.iterations() * NumPoints());
  state.SetBytesProcessed(state.iterations() *
                          static_cast<std::int64_t>(std::filesystem::file_size(file)));
}

void Pcl(benchmark::State& state, const std::string& name) {
  const auto& file = File(name);
  const bool ply = std::filesystem::path(name).extension() == ".ply";
  for (auto _ : state) {
    pcl::PCLPointCloud2 cloud;
    const int rc = ply ? pcl::io::loadPLYFile(file.string(), cloud)
                       : pcl::io::loadPCDFile(file.string(), cloud);
    if (rc < 0) state.SkipWithError("PCL could not read the file");
    benchmark::DoNotOptimize(cloud.data.data());
  }
  state.SetItemsProcessed(state.iterations() * NumPoints());
  state.SetBytesProcessed(state.iterations() *
                          static_cast<std::int64_t>(std::filesystem::file_size(file)));
}

#define BESPOKE_IO_BENCH(file, id)                                                   \
  BENCHMARK_CAPTURE(Bespoke, id, file)->Unit(benchmark::kMillisecond)->MinTime(0.5); \
  BENCHMARK_CAPTURE(Pcl, id, file)->Unit(benchmark::kMillisecond)->MinTime(0.5)

BESPOKE_IO_BENCH("le.ply", ply_binary_le);
BESPOKE_IO_BENCH("be.ply", ply_binary_be);
BESPOKE_IO_BENCH("ascii.ply", ply_ascii);
BESPOKE_IO_BENCH("binary.pcd", pcd_binary);
BESPOKE_IO_BENCH("compressed.pcd", pcd_binary_compressed);
BESPOKE_IO_BENCH("ascii.pcd", pcd_ascii);

}  // namespace
}  // namespace bespoke

BENCHMARK_MAIN();
