#include "resize/ga/operators.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bespoke {
namespace {

double Uniform(Rng& rng) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }

}  // namespace

void UniformCrossover(const BlockSet& blocks, double min_gap_mm, Rng& rng, Eigen::VectorXd* a,
                      Eigen::VectorXd* b) {
  thread_local std::vector<int> swapped;  // control points swapped in the current block
  for (const Block& block : blocks.blocks) {
    const int n = block.nu * block.nv;
    swapped.clear();
    for (int k = 0; k < n; ++k) {
      if (Uniform(rng) < 0.5) continue;
      std::swap((*a)[block.offset + 2 * k], (*b)[block.offset + 2 * k]);
      std::swap((*a)[block.offset + 2 * k + 1], (*b)[block.offset + 2 * k + 1]);
      swapped.push_back(block.offset + 2 * k);
    }
    // A child whose grid folds keeps its parent's block: the parent's
    // values at the swapped points are now the other child's.
    const bool a_ok = BlockValid(block, a->data(), min_gap_mm);
    const bool b_ok = BlockValid(block, b->data(), min_gap_mm);
    if (a_ok && b_ok) continue;
    for (int g : swapped)
      for (int c = g; c < g + 2; ++c) {
        if (!a_ok && !b_ok)
          std::swap((*a)[c], (*b)[c]);
        else if (!a_ok)
          (*a)[c] = (*b)[c];
        else
          (*b)[c] = (*a)[c];
      }
  }
}

void NonUniformMutation(const BlockSet& blocks, const MutationParams& p, Rng& rng,
                        Eigen::VectorXd* genes) {
  const double progress =
      std::clamp(static_cast<double>(p.generation) / p.max_generations, 0.0, 1.0);
  const double power = std::pow(1.0 - progress, p.exponent);
  for (const Block& block : blocks.blocks) {
    const bool along_u = Uniform(rng) < 0.5;
    const int line = static_cast<int>(Uniform(rng) * (along_u ? block.nv : block.nu)) %
                     (along_u ? block.nv : block.nu);
    const int count = along_u ? block.nu : block.nv;
    const double t = p.range_fraction * (along_u ? block.extent_x : block.extent_y);
    auto index = [&](int k) {
      return along_u ? block.offset + 2 * (line * block.nu + k)
                     : block.offset + 2 * (k * block.nu + line) + 1;
    };
    thread_local std::vector<double> original;
    original.resize(count);
    for (int k = 0; k < count; ++k) original[k] = (*genes)[index(k)];
    bool valid = false;
    for (int attempt = 0; attempt < 20 && !valid; ++attempt) {
      for (int k = 0; k < count; ++k) {
        const double delta = t * (1.0 - std::pow(Uniform(rng), power));
        (*genes)[index(k)] = original[k] + (Uniform(rng) < 0.5 ? delta : -delta);
      }
      valid = along_u ? RowOrdered(block, genes->data(), line, p.min_gap_mm)
                      : ColumnOrdered(block, genes->data(), line, p.min_gap_mm);
    }
    if (!valid)
      for (int k = 0; k < count; ++k) (*genes)[index(k)] = original[k];
  }
}

double LifeSpan(double cost, double cost_min, double cost_max, double cost_mean, double life_min,
                double life_max) {
  const double eta = 0.5 * (life_max - life_min);
  if (cost >= cost_mean) {
    const double span = cost_max - cost_mean;
    return life_min + (span > 0 ? eta * (cost_max - cost) / span : eta);
  }
  const double span = cost_mean - cost_min;
  return 0.5 * (life_min + life_max) + (span > 0 ? eta * (cost_mean - cost) / span : eta);
}

void AddGaussianNoise(const BlockSet& blocks, double sigma_mm, double min_gap_mm, Rng& rng,
                      Eigen::VectorXd* genes) {
  std::normal_distribution<double> noise(0.0, sigma_mm);
  for (const Block& block : blocks.blocks) {
    const int n = 2 * block.nu * block.nv;
    const Eigen::VectorXd seed = genes->segment(block.offset, n);
    bool valid = false;
    for (int attempt = 0; attempt < 20 && !valid; ++attempt) {
      for (int k = 0; k < n; ++k) (*genes)[block.offset + k] = seed[k] + noise(rng);
      valid = BlockValid(block, genes->data(), min_gap_mm);
    }
    if (!valid) genes->segment(block.offset, n) = seed;
  }
}

}  // namespace bespoke
