#include "measure/measurements/narrowest_section.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace bespoke {
namespace {

// The points of `cloud` with z in [lo, hi] (mm), with their normals (when
// given) and member flags (one_part off: each level's part is the seed's
// loop with its arcs): a search over many levels slices this band
// instead of the whole cloud.
struct Band {
  Eigen::MatrixX3d points, normals;
  SectionMembers members;
};

std::vector<bool> RowsOf(const std::vector<bool>& flags, const std::vector<Eigen::Index>& rows) {
  std::vector<bool> out(flags.empty() ? 0 : rows.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = flags[static_cast<std::size_t>(rows[i])];
  return out;
}

Band BandOf(const Eigen::MatrixX3d& cloud, const Eigen::MatrixX3d& normals,
            const SectionMembers& members, double lo, double hi) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index r = 0; r < cloud.rows(); ++r)
    if (cloud(r, 2) >= lo && cloud(r, 2) <= hi) rows.push_back(r);
  const bool with_normals = normals.rows() == cloud.rows();
  Band band;
  band.points.resize(static_cast<Eigen::Index>(rows.size()), 3);
  band.normals.resize(with_normals ? band.points.rows() : 0, 3);
  for (size_t i = 0; i < rows.size(); ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    band.points.row(k) = cloud.row(rows[i]);
    if (with_normals) band.normals.row(k) = normals.row(rows[i]);
  }
  band.members = {RowsOf(members.leave_out, rows), RowsOf(members.gap_only, rows), false,
                  members.tape_points};
  return band;
}

// A limb's section between its ankle and calf changes by less than half
// over the band (ankle girth over calf girth is about 0.6): a level whose
// girth is under kSliverShare of the band's median is a sliver the anchor
// picked where a sparse scan left only a few points of the loop (a run of
// them outlasts the median window).
constexpr double kSliverShare = 0.5;

// `z` and `girth` (#L each) without the levels whose girth is a sliver's.
void DropSlivers(std::vector<double>* z, std::vector<double>* girth) {
  if (girth->empty()) return;
  std::vector<double> sorted = *girth;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double floor = kSliverShare * sorted[sorted.size() / 2];
  size_t kept = 0;
  for (size_t i = 0; i < girth->size(); ++i)
    if ((*girth)[i] >= floor) (*z)[kept] = (*z)[i], (*girth)[kept] = (*girth)[i], ++kept;
  z->resize(kept), girth->resize(kept);
}

}  // namespace

double NarrowestSectionZ(const SectionGirthOptions& options, const Eigen::MatrixX3d& cloud,
                         const Eigen::MatrixX3d& normals, double z_from, double z_to,
                         double step_mm, int window, const Eigen::MatrixX3d& anchors,
                         const SectionMembers& members) {
  if (!(step_mm > 0) || !(z_to > z_from) || window < 1) return z_from;
  // No slab is thicker than the widest one.
  const double margin = std::max(options.half_thickness_mm, options.max_half_thickness_mm) + 1;
  const Band band = BandOf(cloud, normals, members, z_from - margin, z_to + margin);
  std::vector<double> z, girth, closed_z, closed_girth;
  Eigen::MatrixX3d at = anchors;
  for (double level = z_from; level <= z_to; level += step_mm) {
    at.col(2).setConstant(level);
    const SectionGirth s =
        MeasureSectionGirth(options, band.points, band.normals, Eigen::Vector3d(0, 0, level),
                            Eigen::Vector3d::UnitZ(), at, band.members);
    if (s.points == 0) continue;
    z.push_back(level), girth.push_back(s.girth_mm);
    if (!s.open) closed_z.push_back(level), closed_girth.push_back(s.girth_mm);
  }
  // An open section's hull spans only the arc the scan saw: where enough
  // levels close their loop, only those are compared.
  if (closed_z.size() >= 2 * static_cast<size_t>(window)) z = closed_z, girth = closed_girth;
  DropSlivers(&z, &girth);
  const int n = static_cast<int>(z.size()), half = window / 2;
  double best = std::numeric_limits<double>::infinity(), best_z = z_from;
  for (int i = half; i + half < n; ++i) {
    std::vector<double> near(girth.begin() + i - half, girth.begin() + i + half + 1);
    std::nth_element(near.begin(), near.begin() + half, near.end());
    if (near[static_cast<size_t>(half)] < best)
      best = near[static_cast<size_t>(half)], best_z = z[static_cast<size_t>(i)];
  }
  return best_z;
}

}  // namespace bespoke
