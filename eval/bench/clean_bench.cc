// Speed of the cleaning chain, and of its hand-written stages against the
// PCL classes they replace, in the same process (Google Benchmark).
//
//   build/eval/bench/clean_bench [--benchmark_filter=Chain]
//   BESPOKE_CLEAN_BENCH_SPACING_MM  sample spacing of the synthetic scene
//                                   (default 3.5: ~440k points)
//
// The scene: oracle/scene/synthetic_scene.h (a person on a 1.6 m floor, a
// pole, stray points), randomly rotated. The stage comparisons run on that
// scene voxelised at 4 mm, as in the chain:
//   Neighbours+SOR+ROR+Normals (ours: one shared FLANN query) vs PCL's
//     StatisticalOutlierRemoval + RadiusOutlierRemoval + NormalEstimationOMP
//   EuclideanClusters (grid union-find) vs pcl::EuclideanClusterExtraction
//   VoxelGrid (ours, all attributes) vs pcl::VoxelGrid<PointXYZ>
// Compare rows as ratios; absolute times depend on the machine and its load.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/radius_outlier_removal.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <cstdlib>

#include "oracle/scene/synthetic_scene.h"
#include "scanners/clean/clean.h"
#include "scanners/clean/neighbours.h"

namespace bespoke {
namespace {

const testing::SyntheticScene& Scene() {
  static const testing::SyntheticScene scene = [] {
    testing::SyntheticSceneOptions options;
    const char* env = std::getenv("BESPOKE_CLEAN_BENCH_SPACING_MM");
    options.spacing_mm = env ? std::atof(env) : 3.5;
    options.scanner_from_body = testing::RandomRigid(7, 1500.0);
    return testing::MakeSyntheticScene(options);
  }();
  return scene;
}

const PointCloud& Voxelised() {
  static const PointCloud cloud = VoxelGridDownsample(VoxelGridOptions{}, Scene().cloud);
  return cloud;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr ToPcl(const PointCloud& cloud) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr out(new pcl::PointCloud<pcl::PointXYZ>);
  out->resize(static_cast<size_t>(cloud.size()));
  for (Eigen::Index i = 0; i < cloud.size(); ++i) {
    (*out)[static_cast<size_t>(i)] =
        pcl::PointXYZ(cloud.points(i, 0), cloud.points(i, 1), cloud.points(i, 2));
  }
  return out;
}

void BM_Chain(benchmark::State& state) {
  const PointCloud& input = Scene().cloud;  // generated outside the timing
  for (auto _ : state) {
    CleanResult result = CleanScan(CleanOptions{}, input);
    benchmark::DoNotOptimize(result.cloud.points.data());
    state.counters["points_out"] = static_cast<double>(result.cloud.size());
  }
  state.counters["points_in"] = static_cast<double>(Scene().cloud.size());
}
BENCHMARK(BM_Chain)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

void BM_Ours_NeighboursOutliersNormals(benchmark::State& state) {
  const PointCloud& cloud = Voxelised();
  for (auto _ : state) {
    const NeighbourLists nn = FindNearestNeighbours(cloud.points, 16);
    const OutlierTest sor = StatisticalOutliers(StatisticalOutlierOptions{}, nn);
    const OutlierTest ror = RadiusOutliers(RadiusOutlierOptions{}, nn);
    const OrientedNormals normals = EstimateOutwardNormals(NormalOptions{}, cloud.points, nn);
    benchmark::DoNotOptimize(normals.normals.data());
    benchmark::DoNotOptimize(sor.keep.size() + ror.keep.size());
  }
  state.counters["points"] = static_cast<double>(cloud.size());
}
BENCHMARK(BM_Ours_NeighboursOutliersNormals)->Unit(benchmark::kMillisecond)->UseRealTime();

// Reference: PCL's classes, each with its own search; normals unoriented.
void BM_Pcl_SorRorNormalEstimationOmp(benchmark::State& state) {
  const auto cloud = ToPcl(Voxelised());
  for (auto _ : state) {
    pcl::Indices sor_kept, ror_kept;
    pcl::StatisticalOutlierRemoval<pcl::PointXYZ> sor;
    sor.setInputCloud(cloud);
    sor.setMeanK(16);
    sor.setStddevMulThresh(5.0);
    sor.filter(sor_kept);
    pcl::RadiusOutlierRemoval<pcl::PointXYZ> ror;
    ror.setInputCloud(cloud);
    ror.setRadiusSearch(15.0);
    ror.setMinNeighborsInRadius(4);
    ror.filter(ror_kept);
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> normals;
    normals.setNumberOfThreads(omp_get_max_threads());
    normals.setInputCloud(cloud);
    normals.setKSearch(17);  // PCL's k counts the point itself
    pcl::PointCloud<pcl::Normal> out;
    normals.compute(out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["points"] = static_cast<double>(cloud->size());
}
BENCHMARK(BM_Pcl_SorRorNormalEstimationOmp)->Unit(benchmark::kMillisecond)->UseRealTime();

// The floor stage alone on the voxelised scene: (ransac_sample, max_planes).
void BM_Floor(benchmark::State& state) {
  const PointCloud& cloud = Voxelised();
  FloorOptions options;
  options.ransac_sample = static_cast<int>(state.range(0));
  options.max_planes = static_cast<int>(state.range(1));
  for (auto _ : state) {
    const FloorResult floor = RemoveFloor(options, cloud.points);
    benchmark::DoNotOptimize(floor.keep.size());
    state.counters["found"] = floor.found;
    state.counters["candidates"] = floor.candidates;
  }
}
BENCHMARK(BM_Floor)
    ->Args({20000, 3})
    ->Args({20000, 1})
    ->Args({5000, 3})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_Ours_EuclideanClusters(benchmark::State& state) {
  const PointCloud& cloud = Voxelised();
  for (auto _ : state) {
    const Clusters clusters = EuclideanClusters(ClusterOptions{}, cloud.points);
    benchmark::DoNotOptimize(clusters.label.data());
  }
}
BENCHMARK(BM_Ours_EuclideanClusters)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Pcl_EuclideanClusterExtraction(benchmark::State& state) {
  const auto cloud = ToPcl(Voxelised());
  for (auto _ : state) {
    pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
    pcl::EuclideanClusterExtraction<pcl::PointXYZ> extraction;
    extraction.setClusterTolerance(ClusterOptions{}.tolerance_mm);
    extraction.setMinClusterSize(1);
    extraction.setMaxClusterSize(1 << 30);
    extraction.setSearchMethod(tree);
    extraction.setInputCloud(cloud);
    std::vector<pcl::PointIndices> clusters;
    extraction.extract(clusters);
    benchmark::DoNotOptimize(clusters.data());
  }
}
BENCHMARK(BM_Pcl_EuclideanClusterExtraction)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Ours_VoxelGrid(benchmark::State& state) {
  const PointCloud& input = Scene().cloud;
  for (auto _ : state) {
    PointCloud out = VoxelGridDownsample(VoxelGridOptions{}, input);
    benchmark::DoNotOptimize(out.points.data());
  }
}
BENCHMARK(BM_Ours_VoxelGrid)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Pcl_VoxelGrid(benchmark::State& state) {
  const auto cloud = ToPcl(Scene().cloud);
  for (auto _ : state) {
    pcl::VoxelGrid<pcl::PointXYZ> grid;
    grid.setInputCloud(cloud);
    grid.setLeafSize(4.0f, 4.0f, 4.0f);
    pcl::PointCloud<pcl::PointXYZ> out;
    grid.filter(out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_Pcl_VoxelGrid)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace bespoke

BENCHMARK_MAIN();
