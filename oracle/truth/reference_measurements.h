// The exact reference measurements of a generated body: every catalogue
// measurement computed on the mesh itself, the ground truth that Bespoke's
// measurements from scans are judged against.
//
//   girth  (section_hull)  perimeter of the 2-D convex hull of the exact
//          mesh-plane section loop of the body part measured: with one datum
//          point the loop through (nearest) it, with several the loop that
//          encloses their centroid (so the hip loop, not the hands beside it);
//          for a trunk girth whose centroid no loop encloses (breasts hanging
//          clear of the chest, cut as loops of their own) the largest loop.
//          The plane: horizontal at the mean height of the datum points; or
//          through datum[0] perpendicular to axis[0] -> axis[1]; or through
//          the three datum points (mesh_section.h). MeasurementDef::arms
//          "lower" moves a horizontal plane down until the trunk is free of
//          the arms (chest: just under the armpits).
//   length (geodesic)      sum of exact geodesics (CGAL, each on a crop of
//          the mesh that provably holds it: cropped_geodesics.h) along the datum
//          chain, + the last point's height when to_floor; (breadth) the
//          horizontal distance; (point_to_line) the 3-D point-line distance.
//   height                 z of datum[0] (the floor is z = 0), or z[0] - z[1].
//
// Input: a Body (body frame, mm; closed mesh; landmarks as surface points).
// Measurements whose datum points the body lacks are skipped (listed with
// the reason), not guessed. Flags (ReferenceMeasurement::flags):
//   "section_open"           the chosen loop is not closed (mesh boundary)
//   "datum_off_section"      the first datum point is farther than
//                            datum_tolerance_mm from the chosen loop
//   "section_crosses_midline" a right-side limb girth whose loop reaches
//                            x <= 0 (thighs touching, arm against the trunk)
//   "section_limb_only"      such a loop, with limb labels (Body::limbs),
//                            replaced by the section of the limb's own faces:
//                            a posed limb passing into the trunk or the other
//                            leg (its loops within 100 mm of the datum point)
//   "section_includes_arms"  a trunk girth (arms "check"/"lower") whose loop
//                            reaches > 30 mm beyond its lateral datum points
// Failure: InputError for an invalid mesh (ExactGeodesics' checks) or bad
// options; InternalError when a section is empty.
#ifndef BESPOKE_ORACLE_TRUTH_REFERENCE_MEASUREMENTS_H_
#define BESPOKE_ORACLE_TRUTH_REFERENCE_MEASUREMENTS_H_

#include <string>
#include <utility>
#include <vector>

#include "measure/catalogue/catalogue.h"
#include "oracle/body/body.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct ReferenceOptions {
  double datum_tolerance_mm = 20;  // default 20 mm; see "datum_off_section"
  bool keep_geometry = false;      // default false; fill ReferenceMeasurement::geometry
  // Throws InputError when datum_tolerance_mm is not positive.
  void Check() const;
};

struct ReferenceMeasurement {
  std::string name;
  MeasurementKind kind = MeasurementKind::kLength;
  double value_mm = 0;
  std::vector<std::string> flags;
  // With keep_geometry: the hull polygon (girth, #K x 3, closed implicitly)
  // or the geodesic polyline (length, #K x 3); empty otherwise.
  Eigen::MatrixX3d geometry;
};

struct ReferenceMeasurements {
  std::vector<ReferenceMeasurement> measurements;            // catalogue order
  std::vector<std::pair<std::string, std::string>> skipped;  // name, reason
};

ReferenceMeasurements ComputeReferenceMeasurements(const ReferenceOptions& options,
                                                   const Catalogue& catalogue, const Body& body,
                                                   Progress* progress = nullptr);

// The girth plane of a section_hull measurement for the body's landmarks:
// a point on it and its unit normal (mm, body frame). InputError when the
// measurement is not a girth or a landmark is missing.
std::pair<Eigen::Vector3d, Eigen::Vector3d> GirthPlaneOf(const MeasurementDef& measurement,
                                                         const Body& body);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_TRUTH_REFERENCE_MEASUREMENTS_H_
