// Made-to-measure pattern resizing with the multi-objective genetic algorithm
// of thesis chapter 4 (NSGA-II selection with pagmo's non-dominated sorting
// and crowding distance), started from a graded pattern and followed by a
// constrained polish.
//
// Input: a base pattern (validated, with bindings) and the body's
// measurements (mm, catalogue names; every bound measurement must be
// present after the derived ones are added, AddDerivedMeasurements;
// bindings that keep the base's ease need Pattern::base_body).
// Only the pieces a binding or seam reaches are fitted; every other piece is
// copied from the base unchanged. Steps: the graded start (grader.h); the GA,
// its population the graded start plus noise, its shape objective the
// turning-angle change from the base (objectives.h); the polish, projecting
// the GA's pick onto the bindings, seams and structure rules (polish.h),
// falling back to the graded start when the projection fails. With 0
// generations the GA is skipped and the graded start is polished.
// Output: the fitted pattern, its objective values before and after the
// polish, the final Pareto front, per-generation statistics, the graded
// start, and the proportional-grading seed for comparison.
//
// Deterministic for a given seed whatever the thread count: the run's
// generator seeds one generator per mating pair and per rebirth, in order,
// and breeding and the pure fitness evaluation run in parallel (TBB), as
// do the two polishes. Errors: InputError for bad options, unknown or
// missing measurements.
#ifndef BESPOKE_RESIZE_GA_RESIZE_H_
#define BESPOKE_RESIZE_GA_RESIZE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "resize/ga/block.h"
#include "resize/ga/grader.h"
#include "resize/ga/objectives.h"
#include "resize/ga/polish.h"
#include "resize/pattern/measurements.h"
#include "resize/pattern/pattern.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct ResizeOptions {
  int population = 400;                // individuals (thesis: 400). Even, >= 8.
  int generations = 200;               // generations (thesis: 200)
  std::uint64_t seed = 1;              // random seed; same seed, same result
  double crossover_rate = 0.9;         // probability a mating pair is recombined. Default 0.9.
  double mutation_rate = 0.6;          // at generation 0 (thesis: 0.6)
  double mutation_rate_step = 0.002;   // subtracted per generation (thesis: 0.002)
  double mutation_rate_min = 0.05;     // floor. Default 0.05.
  double mutation_exponent = 2;        // r of Eq 4.4. Default 2.
  double mutation_range = 0.05;        // t of Eq 4.4 as a fraction of the block size. Default 0.05.
  double noise_sigma_mm = 1;           // Gaussian noise of the initial population (thesis: unit)
  double life_min = 3, life_max = 12;  // generations, Eq 4.2. Defaults 3 and 12.
  double tolerance_mm = 1;             // measurement tolerance of the final pick. Default 1 mm.
  double min_gap_mm = 0.1;             // grid ordering gap. Default 0.1 mm.
  bool polish = true;                  // run the constrained polish. Default on.
  int threads = 0;                     // threads to use; 0 (default) = all CPUs
  // Start the GA from the graded pattern (grader.h); off: from the
  // proportional seed (Algorithm 6), as the thesis does. Default on.
  bool graded_start = true;
  // The shape objective measures change from the graded start (a grader's
  // shape for this body) when it is the start; off: from the base, as the
  // thesis does. Default on.
  bool shape_from_graded = true;
  GraderOptions grader_options;
  PolishOptions polish_options;
  BlockOptions block_options;
  void Check() const;  // InputError naming the bad option
};

struct GenerationStats {
  int generation = 0;
  double best_measurement_mm = 0;  // least Eq 4.5 in the population
  double best_seam = 0;
  double best_shape_deg = 0;
  int front_size = 0;
};

struct ResizeResult {
  Pattern fitted;            // the final answer
  Objectives ga_objectives;  // the GA's pick, before the polish
  Objectives objectives;     // the final answer
  PolishReport polish;
  std::string polish_start = "none";  // which start the kept polish came from: "ga" or "graded"
  std::vector<Objectives> front;      // final first front
  std::vector<GenerationStats> history;
  Pattern seed;  // proportional scaling (Algorithm 6)
  Objectives seed_objectives;
  std::string shape_reference = "base";    // what the shape objective measures change from
  Pattern graded;                          // the graded start (grader.h), or the seed when off
  Objectives graded_objectives;            // of the graded start
  double graded_constraint_mm = 0;         // largest binding, seam or structure error it left (mm)
  std::vector<std::string> fitted_pieces;  // the pieces fitted (a binding or seam reaches them)
  std::vector<double> targets_mm, achieved_mm;  // per binding
  std::vector<double> seam_mismatch_mm;         // per seam: length(a) - length(b) - ease
  double ga_time_s = 0, polish_time_s = 0;
};

ResizeResult ResizePattern(const ResizeOptions& options, const Pattern& base,
                           const MeasurementSet& body, Progress* progress);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_RESIZE_H_
