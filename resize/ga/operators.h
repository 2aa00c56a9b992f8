// The genetic operators of thesis 4.2.2-4.2.3, on gene vectors (block.h).
//
// Crossover (Algorithm 7): uniform, block by block: each control point (both
//   coordinates) of child 1 comes from parent 1 or 2 with probability 1/2,
//   child 2 gets the other. Deviation: a child block that breaks the
//   row/column ordering is replaced by the corresponding parent block (the
//   thesis does not say what happens then).
// Mutation (Algorithm 8 + Eq 4.3-4.4, Michalewicz's non-uniform mutation):
//   for every block, u or v with probability 1/2; one random row (u: the x
//   of its control points) or column (v: the y) is moved, each value by
//   +/- Delta(gen, t) = t (1 - lambda^((1 - gen/G)^r)), lambda ~ U(0, 1), the
//   sign by a fair coin (the thesis's "normal gamma >= 0.5" would move up only
//   31 % of the time), t = range_fraction x the block's extent. A draw that
//   breaks the ordering of that row/column is redrawn (up to 20 times, then
//   the block is left unchanged).
// Ageing (Eq 4.2, the bilinear life span of Michalewicz's GAVaPS).
#ifndef BESPOKE_RESIZE_GA_OPERATORS_H_
#define BESPOKE_RESIZE_GA_OPERATORS_H_

#include <Eigen/Core>
#include <random>

#include "resize/ga/block.h"

namespace bespoke {

using Rng = std::mt19937_64;

struct MutationParams {
  int generation = 0;            // gen
  int max_generations = 1;       // Gen_max
  double exponent = 2;           // r of Eq 4.4
  double range_fraction = 0.05;  // t = fraction x block extent along the mutated axis
  double min_gap_mm = 0.1;       // ordering gap kept between grid lines (mm)
};

void UniformCrossover(const BlockSet& blocks, double min_gap_mm, Rng& rng, Eigen::VectorXd* a,
                      Eigen::VectorXd* b);

void NonUniformMutation(const BlockSet& blocks, const MutationParams& params, Rng& rng,
                        Eigen::VectorXd* genes);

// Eq 4.2: life span of an individual with scalar cost `cost` given the
// population's min, max and expected (mean) cost; eta = (max - min) / 2.
double LifeSpan(double cost, double cost_min, double cost_max, double cost_mean, double life_min,
                double life_max);

// Adds N(0, sigma) to every control point coordinate of every block; a block
// whose ordering breaks is redrawn (up to 20 times, then left at its seed).
void AddGaussianNoise(const BlockSet& blocks, double sigma_mm, double min_gap_mm, Rng& rng,
                      Eigen::VectorXd* genes);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_OPERATORS_H_
