#include "eval/validate/validate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/errors.h"

namespace bespoke {

void ValidateOptions::Check() const {
  geodesics.Check();
  poisson.Check();
}

namespace {

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void Summarise(ValidationReport* report) {
  double sum_abs = 0, sum_rel = 0;
  for (const PairComparison& c : report->pairs) {
    if (!c.error.empty()) continue;
    ++report->compared;
    sum_abs += c.abs_diff_mm;
    sum_rel += std::abs(c.rel_diff);
    report->max_abs_mm = std::max(report->max_abs_mm, c.abs_diff_mm);
    report->max_rel = std::max(report->max_rel, std::abs(c.rel_diff));
  }
  if (report->compared > 0) {
    report->mean_abs_mm = sum_abs / report->compared;
    report->mean_rel = sum_rel / report->compared;
  }
}

}  // namespace

ValidationReport ValidateGeodesics(const ValidateOptions& options, const PointCloud& cloud,
                                   const std::vector<GeodesicPair>& pairs, Progress* progress) {
  options.Check();
  if (pairs.empty()) throw InputError("validate: no pairs of points to compare");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ValidationReport report;
  report.pairs.resize(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) report.pairs[i].pair = pairs[i];

  auto start = std::chrono::steady_clock::now();
  CloudGeodesics geodesics(options.geodesics, cloud.points, progress);
  for (PairComparison& c : report.pairs) {
    try {
      c.cloud_mm = geodesics.Between(c.pair.from, c.pair.to).length_mm;
    } catch (const InputError& e) {
      c.cloud_mm = nan;
      c.error = std::string("cloud: ") + e.what();
    }
  }
  report.cloud_time_s = Seconds(start);

  start = std::chrono::steady_clock::now();
  report.mesh = ReconstructPoisson(options.poisson, cloud, progress);
  report.mesh_vertices = report.mesh.num_vertices();
  report.mesh_faces = report.mesh.num_faces();
  report.reconstruction_time_s = Seconds(start);

  start = std::chrono::steady_clock::now();
  ExactGeodesics exact(report.mesh);
  // Pairs sharing a start point share CGAL's propagation (it caches the last
  // source), so visit them grouped by start point.
  std::vector<size_t> order(pairs.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::lexicographical_compare(pairs[a].from.data(), pairs[a].from.data() + 3,
                                        pairs[b].from.data(), pairs[b].from.data() + 3);
  });
  ProgressBegin(progress, "exact geodesics on the reference mesh",
                static_cast<std::int64_t>(pairs.size()));
  std::int64_t done = 0;
  for (const size_t i : order) {
    PairComparison& c = report.pairs[i];
    try {
      c.mesh_mm = exact.Distance(c.pair.from, c.pair.to);
    } catch (const InputError& e) {
      c.mesh_mm = nan;
      c.error += std::string(c.error.empty() ? "" : "; ") + "mesh: " + e.what();
    }
    if (c.error.empty()) {
      c.abs_diff_mm = std::abs(c.cloud_mm - c.mesh_mm);
      c.rel_diff = c.mesh_mm > 0 ? (c.cloud_mm - c.mesh_mm) / c.mesh_mm : 0.0;
    }
    ProgressUpdate(progress, ++done);
  }
  ProgressEnd(progress);
  report.exact_time_s = Seconds(start);
  Summarise(&report);
  return report;
}

std::vector<GeodesicPair> SpreadPairs(const PointCloud& cloud, int count, unsigned seed) {
  if (count < 1) throw InputError("validate: the number of pairs must be >= 1");
  if (cloud.size() < 2) throw InputError("validate: the cloud has fewer than 2 points");
  const Eigen::AlignedBox3d box(cloud.points.colwise().minCoeff().transpose(),
                                cloud.points.colwise().maxCoeff().transpose());
  const double diagonal = box.diagonal().norm();
  std::mt19937 rng(seed);
  std::uniform_int_distribution<Eigen::Index> pick(0, cloud.size() - 1);
  std::vector<GeodesicPair> pairs;
  for (int tries = 0; static_cast<int>(pairs.size()) < count && tries < 100000; ++tries) {
    const Eigen::Index a = pick(rng), b = pick(rng);
    const double d = (cloud.points.row(a) - cloud.points.row(b)).norm();
    if (d < 0.2 * diagonal || d > 0.6 * diagonal) continue;
    pairs.push_back({"pair_" + std::to_string(pairs.size() + 1), cloud.points.row(a).transpose(),
                     cloud.points.row(b).transpose()});
  }
  if (pairs.empty()) throw InputError("validate: could not choose pairs of points on the scan");
  return pairs;
}

}  // namespace bespoke
