#include "measure/measurements/geodesic_plan.h"

#include <algorithm>
#include <limits>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Pair = std::pair<std::string, std::string>;

// Distances (mm) from `x` to every site.
std::vector<double> Distances(const Eigen::MatrixX3d& sites, const Eigen::Vector3d& x) {
  std::vector<double> d(static_cast<size_t>(sites.rows()));
  for (Eigen::Index i = 0; i < sites.rows(); ++i)
    d[static_cast<size_t>(i)] = (sites.row(i).transpose() - x).norm();
  return d;
}

// The sites within r (mm): a ball's estimated cost.
double Within(const std::vector<double>& distances, double r) {
  return static_cast<double>(
      std::count_if(distances.begin(), distances.end(), [r](double d) { return d <= r; }));
}

// The pair's chord (mm), longest first; ties by name for a fixed order.
std::vector<std::pair<double, Pair>> ByChord(const std::map<std::string, PlanEnd>& ends,
                                             const std::set<Pair>& pairs) {
  std::vector<std::pair<double, Pair>> out;
  for (const Pair& p : pairs)
    out.emplace_back((ends.at(p.first).position_mm - ends.at(p.second).position_mm).norm(), p);
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  return out;
}

}  // namespace

std::vector<SourceGroup> PlanSources(const Eigen::MatrixX3d& sites,
                                     const std::map<std::string, PlanEnd>& ends,
                                     const std::set<Pair>& pairs) {
  std::map<std::string, std::vector<double>> distances;
  for (const Pair& p : pairs)
    for (const std::string& name : {p.first, p.second}) {
      if (!ends.count(name)) throw InternalError("geodesic plan: no end '" + name + "'");
      if (!distances.count(name)) distances[name] = Distances(sites, ends.at(name).position_mm);
    }
  std::map<std::string, SourceGroup> planned;
  for (const auto& [chord, pair] : ByChord(ends, pairs)) {
    const bool holes = ends.at(pair.first).at_hole && ends.at(pair.second).at_hole;
    std::string best;
    double best_cost = std::numeric_limits<double>::infinity(), best_ball = 0;
    for (const std::string& name : {pair.first, pair.second}) {
      if (ends.at(name).at_hole && !holes) continue;
      const auto it = planned.find(name);
      const bool known = it != planned.end();
      // A planned source grows only beyond the ball it already floods.
      const double ball =
          known && it->second.radius_mm >= chord ? it->second.cost : Within(distances[name], chord);
      const double grows = ball - (known ? it->second.cost : 0.0);
      if (grows < best_cost) best = name, best_cost = grows, best_ball = ball;  // ties: first
    }
    SourceGroup& group = planned[best];
    group.source = best;
    group.pairs.push_back(pair);
    group.radius_mm = std::max(group.radius_mm, chord);
    group.cost = best_ball;
  }
  std::vector<SourceGroup> groups;
  for (auto& entry : planned) groups.push_back(std::move(entry.second));
  std::stable_sort(groups.begin(), groups.end(),
                   [](const SourceGroup& x, const SourceGroup& y) { return x.cost > y.cost; });
  return groups;
}

}  // namespace bespoke
