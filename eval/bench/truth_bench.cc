// Speed of the exact reference (Google Benchmark), as ratios within one run:
// the catalogue's geodesic datum pairs on a body, computed
//   Whole   - the baseline without cropping: one CGAL propagation over the
//             whole mesh per source point, every pair touching that source
//             answered from its tree (sources chosen greedily);
//   Cropped - CroppedExactGeodesics: one propagation per pair on a crop that
//             provably holds its shortest path (cropped_geodesics.h);
// and the whole ComputeReferenceMeasurements (girths, lengths, heights).
// Bodies: the default parametric body and, where ../shared is present (or
// $BESPOKE_SHARED_DIR), MakeHuman seed 1.
//
//   build/eval/bench/truth_bench [--benchmark_filter=Parametric]
//
// Counters: pairs, propagations, faces (mesh), max_diff_mm (largest
// |cropped - whole| over the pairs, in the Cropped rows).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

#include "measure/catalogue/catalogue.h"
#include "oracle/body/parametric_body.h"
#include "oracle/synth/synth_body.h"
#include "oracle/truth/cropped_geodesics.h"
#include "oracle/truth/exact_geodesics.h"
#include "oracle/truth/reference_measurements.h"

namespace bespoke {
namespace {

using Pair = std::pair<std::string, std::string>;

const Body& TheBody(const std::string& model) {
  static std::map<std::string, Body> bodies;
  if (bodies.count(model) == 0) {
    SynthBodyOptions o;
    o.model = model;
    o.seed = model == "parametric" ? 0 : 1;
    bodies[model] = GenerateSynthBody(o);
  }
  return bodies[model];
}

bool HaveMakeHuman() { return std::filesystem::exists(DefaultMakeHumanDir() / "base.obj"); }

std::set<Pair> CataloguePairs() {
  std::set<Pair> pairs;
  for (const MeasurementDef& m : Catalogue::Builtin().measurements())
    if (m.method == MeasurementMethod::kGeodesic)
      for (std::size_t i = 0; i + 1 < m.datum.size(); ++i)
        pairs.insert(std::minmax(m.datum[i], m.datum[i + 1]));
  return pairs;
}

// The former method: whole-mesh propagations, greedy sources.
std::map<Pair, double> WholeMesh(const Body& body, std::int64_t* propagations) {
  std::set<Pair> pending = CataloguePairs();
  std::map<Pair, double> out;
  ExactGeodesics geodesics(body.mesh);
  while (!pending.empty()) {
    std::map<std::string, int> degree;
    for (const auto& [a, b] : pending) ++degree[a], ++degree[b];
    const std::string source =
        std::max_element(degree.begin(), degree.end(), [](const auto& x, const auto& y) {
          return x.second < y.second;
        })->first;
    ++*propagations;
    for (auto it = pending.begin(); it != pending.end();) {
      if (it->first != source && it->second != source) {
        ++it;
        continue;
      }
      const std::string& target = it->first == source ? it->second : it->first;
      out[*it] = geodesics.Distance(body.landmarks.at(source), body.landmarks.at(target));
      it = pending.erase(it);
    }
  }
  return out;
}

void BM_Whole(benchmark::State& state, const std::string& model) {
  if (model == "makehuman" && !HaveMakeHuman()) return state.SkipWithError("needs ../shared");
  const Body& body = TheBody(model);
  std::int64_t propagations = 0;
  for (auto _ : state) benchmark::DoNotOptimize(WholeMesh(body, &propagations));
  state.counters["pairs"] = static_cast<double>(CataloguePairs().size());
  state.counters["propagations"] =
      static_cast<double>(propagations) / static_cast<double>(state.iterations());
  state.counters["faces"] = static_cast<double>(body.mesh.num_faces());
}

// The whole-mesh lengths of a model's pairs (computed once per run).
const std::map<Pair, double>& WholeMeshLengths(const std::string& model) {
  static std::map<std::string, std::map<Pair, double>> lengths;
  std::int64_t unused = 0;
  if (lengths.count(model) == 0) lengths[model] = WholeMesh(TheBody(model), &unused);
  return lengths[model];
}

// state.range(0): CroppedGeodesicsOptions::initial_ratio in percent.
void BM_Cropped(benchmark::State& state, const std::string& model) {
  if (model == "makehuman" && !HaveMakeHuman()) return state.SkipWithError("needs ../shared");
  const Body& body = TheBody(model);
  const std::set<Pair> pairs = CataloguePairs();
  std::map<Pair, double> cropped;
  CroppedGeodesicsStats stats;
  CroppedGeodesicsOptions options;
  options.initial_ratio = static_cast<double>(state.range(0)) / 100;
  for (auto _ : state) {
    CroppedExactGeodesics geodesics(body.mesh, options);
    for (const Pair& p : pairs)
      cropped[p] = geodesics.Distance(body.landmarks.at(p.first), body.landmarks.at(p.second));
    stats = geodesics.stats();
  }
  double max_diff = 0;
  for (const auto& [pair, length] : WholeMeshLengths(model))
    max_diff = std::max(max_diff, std::abs(length - cropped[pair]));
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.counters["propagations"] = static_cast<double>(stats.propagations);
  state.counters["faces"] = static_cast<double>(body.mesh.num_faces());
  state.counters["mean_crop_faces"] =
      static_cast<double>(stats.faces_used) / static_cast<double>(stats.propagations);
  state.counters["max_diff_mm"] = max_diff;
}

void BM_Reference(benchmark::State& state, const std::string& model) {
  if (model == "makehuman" && !HaveMakeHuman()) return state.SkipWithError("needs ../shared");
  const Body& body = TheBody(model);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        ComputeReferenceMeasurements(ReferenceOptions(), Catalogue::Builtin(), body));
  state.counters["faces"] = static_cast<double>(body.mesh.num_faces());
}

BENCHMARK_CAPTURE(BM_Whole, Parametric, std::string("parametric"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Cropped, Parametric, std::string("parametric"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Arg(100)
    ->Arg(105)
    ->Arg(115)
    ->Arg(130);
BENCHMARK_CAPTURE(BM_Reference, Parametric, std::string("parametric"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Whole, MakeHuman, std::string("makehuman"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Cropped, MakeHuman, std::string("makehuman"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Arg(100)
    ->Arg(105)
    ->Arg(115)
    ->Arg(130);
BENCHMARK_CAPTURE(BM_Reference, MakeHuman, std::string("makehuman"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace bespoke

BENCHMARK_MAIN();
