// The level of a girth defined as the smallest section of a band: the
// catalogue's `narrowest_up_to` (the ankle girth, ISO 8559-1's minimum
// above the malleoli: the smallest section up to the calf).
//
// Input and units as MeasureSectionGirth (section_girth.h): #P x 3 cloud
// and #P x 3 normals or 0 x 3 (body frame, mm), heights in mm.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_NARROWEST_SECTION_H_
#define BESPOKE_MEASURE_MEASUREMENTS_NARROWEST_SECTION_H_

#include <Eigen/Core>

#include "measure/measurements/section_girth.h"

namespace bespoke {

// The height (mm) in [z_from, z_to] of the smallest horizontal section: the
// part's girth every step_mm (each with the anchors moved to that height),
// the median of `window` neighbouring levels so that one noisy or broken
// section (a sliver the anchor picks between two holes) does not decide,
// and the level of the smallest median. Levels whose girth is under half
// the band's median are slivers too and left out first: on a sparse scan a
// run of them can outlast the window. Where at least 2 `window` levels
// close their loop, open sections (a hull of the arc the scan saw) are
// left out too. z_from when no level cuts the cloud
// or z_to <= z_from. Arguments as MeasureSectionGirth (members.one_part is
// not used: each level's part is the seed's loop with its arcs).
double NarrowestSectionZ(const SectionGirthOptions& options, const Eigen::MatrixX3d& cloud,
                         const Eigen::MatrixX3d& normals, double z_from, double z_to,
                         double step_mm, int window, const Eigen::MatrixX3d& anchors,
                         const SectionMembers& members = {});

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_NARROWEST_SECTION_H_
