// Non-dominated sorting and best-N selection for the GA's three objectives
// (thesis 4.2.4; NSGA-II, Deb et al. 2002), all minimised.
//
// The same fronts, in the same order, as pagmo::fast_non_dominated_sorting
// and the same choice as pagmo::select_best_N_mo (fronts in order, the last
// one cut by decreasing pagmo::crowding_distance), with the dominance test
// inlined for three objectives and every pair compared once: the sorting
// runs several times per generation over up to 2 x population points, is
// quadratic in their number, and pagmo's generic version of it took a fifth
// of the GA's time.
#ifndef BESPOKE_RESIZE_GA_RANKING_H_
#define BESPOKE_RESIZE_GA_RANKING_H_

#include <array>
#include <vector>

namespace bespoke {

using ObjectivePoint = std::array<double, 3>;

// Fronts of `points` (#points): fronts[0] the non-dominated points, each
// front's indices in the order pagmo gives them; rank[i] the front of i.
struct Fronts {
  std::vector<std::vector<int>> fronts;
  std::vector<int> rank;
};
Fronts SortFronts(const std::vector<ObjectivePoint>& points);

// pagmo's crowding distance of the members of one front (#front, infinite
// at the ends of every objective; a front of 1 or 2 is all ends).
std::vector<double> CrowdingDistance(const std::vector<ObjectivePoint>& front);

// Indices of the best `n` of `points` (n <= #points). With `rank`, also
// each chosen point's front (rank[k] for chosen[k]); whole fronts are
// chosen before a later one, so that is also its front among the chosen.
std::vector<int> SelectBest(const std::vector<ObjectivePoint>& points, int n,
                            std::vector<int>* rank = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_RANKING_H_
