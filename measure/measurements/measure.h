// Tailoring measurements of a scanned person: every catalogue measurement
// (measure/catalogue) taken on the cleaned, body-framed point cloud from its
// datum points, with the same semantics as the exact reference measurements
// of the oracle (oracle/truth/reference_measurements.h) so that the two can
// be compared one to one (docs/measuring.md):
//
//   girth (section_hull)  MeasureSectionGirth (section_girth.h) in the
//         catalogue's plane: horizontal at the mean height of the datum
//         points; through datum[0] perpendicular to axis[0] -> axis[1]; or
//         through the three datum points. arms "lower" (chest: just under
//         the armpits) keeps the points between the datum points' x.
//   length geodesic: CloudGeodesics::Between along the datum chain (one grid
//         per scan, shared by every length), + the last point's height when
//         to_floor; breadth: horizontal distance; point_to_line: 3-D
//         distance from datum[0] to the line through datum[1], datum[2].
//   height z of datum[0] (the floor is z = 0), or z[0] - z[1].
//
// Flags (Measurement::flags), as the reference uses them, plus the scan's own:
//   "section_open"            the hull bridged a scan hole wider than open_gap_mm
//   "datum_off_section"       datum[0] is farther than datum_tolerance_mm from the part's loop
//   "section_crosses_midline" a right-side girth whose loop reaches x <= 0
//   "section_includes_arms"   a trunk girth (arms check/lower) reaching > arms_margin_mm
//                             beyond its lateral datum points
//   "landmark_uncertain"      a datum or axis point has confidence < 0.5 or flags
//                             (names in Measurement::uncertain_landmarks)
//   "datum_off_scan"          a datum point of a length is farther than
//                             datum_tolerance_mm from every scan point (in a
//                             scan hole, e.g. the crotch)
//   "bridged"                 part of a length crosses unscanned skin as an
//                             arc (bridged_mm; geodesic_paths.h: into a hole
//                             up to max_bridge_mm, or across one from its rim
//                             or round which the scan's path detours, when
//                             shorter than over the scan)
// Measurements whose landmarks are missing, or whose geodesic has no path
// over the scan, are listed in `skipped` with the reason, never guessed.
//
// Input: body-frame cloud (#P x 3, mm; normals unused), landmarks in the
// body frame (mm). Failure: InputError for bad options or an empty cloud.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_MEASURE_H_
#define BESPOKE_MEASURE_MEASUREMENTS_MEASURE_H_

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "measure/catalogue/catalogue.h"
#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "measure/landmarks/landmarks.h"
#include "measure/measurements/section_girth.h"
#include "measure/measurements/uncertainty.h"
#include "scanners/core/progress.h"
#include "scanners/core/types.h"

namespace bespoke {

struct MeasureOptions {
  SectionGirthOptions section;      // girth sections (defaults in section_girth.h)
  CloudGeodesicsOptions geodesics;  // geodesic lengths (defaults in cloud_geodesics.h)
  UncertaintyOptions uncertainty;   // uncertainty_mm (defaults in uncertainty.h)
  double datum_tolerance_mm = 20;   // default 20 mm: "datum_off_section" / "datum_off_scan"
  double max_bridge_mm = 120;    // default 120 mm: a datum point this far in a scan hole is bridged
  double arms_margin_mm = 30;    // default 30 mm: "section_includes_arms" beyond the datums' x
  double narrowest_step_mm = 2;  // default 2 mm: level step of a "narrowest_up_to" girth
  int narrowest_window = 5;      // default 5: levels whose median is compared there
  double uncertain_confidence = 0.5;  // default 0.5: below it a landmark is "uncertain"
  int geodesic_threads = 2;           // default 2: threads for the geodesic lengths (one
                                      // grid shared, each its own propagation cache)
  // default true: from the body structure's parts (the landmarks' parts, else
  // found here) a trunk girth keeps the trunk's points, an arm's girth that
  // arm's, another girth leaves out the arms
  bool separate_arms = true;
  bool keep_geometry = true;      // default true: hull loops and paths for rendering
  std::vector<std::string> only;  // default empty = every catalogue measurement
  void Check() const;             // InputError when out of range
};

struct Measurement {
  std::string name;
  MeasurementKind kind = MeasurementKind::kLength;
  MeasurementMethod method = MeasurementMethod::kGeodesic;
  std::vector<std::string> datum;  // the catalogue's datum points
  double value_mm = 0;
  std::vector<std::string> flags;  // quality flags (see above); empty when clean
  std::vector<std::string> uncertain_landmarks;
  // With keep_geometry: girth -> the hull polygon (#K x 3, closed implicitly);
  // geodesic -> the path (#K x 3, chain pieces concatenated); breadth and
  // point_to_line -> the two end points; height -> the point and its floor foot.
  Eigen::MatrixX3d geometry;
  // Girths: the plane used (body frame, mm).
  Eigen::Vector3d plane_point = Eigen::Vector3d::Zero(), plane_normal = Eigen::Vector3d::Zero();
  double largest_gap_mm = 0;  // girths: widest hole bridged by the hull
  // Geodesic lengths: how much of value_mm was bridged across unscanned
  // skin (the crotch, an armpit) rather than measured over the scan.
  double bridged_mm = 0;
  // Half width of the 95 % interval around value_mm (uncertainty.h).
  double uncertainty_mm = 0;
};

struct MeasureStage {
  std::string name;   // "girths", "geodesic_grid", "geodesics", "lengths_other"
  double time_s = 0;  // wall
  double cpu_s = 0;   // process CPU, all threads
};

// How densely the scan samples the skin, and the girth slab that follows
// from it (SlabForSpacing, section_girth.h). mm.
struct ScanSampling {
  double noise_mm = 0;                // RMS distance of points from their local planes
  double spacing_mm = 0;              // median nearest-neighbour distance
  double surface_spacing_mm = 0;      // side of the square of skin per point
  double slab_half_thickness_mm = 0;  // girth slab used
  double piece_gap_mm = 0;            // girth piece gap used
};

struct MeasureResult {
  std::vector<Measurement> measurements;                     // catalogue order
  std::vector<std::pair<std::string, std::string>> skipped;  // name, reason
  ScanSampling sampling;
  std::vector<MeasureStage> stages;
  double total_time_s = 0;
  const Measurement* Find(const std::string& name) const;  // nullptr when absent
};

MeasureResult Measure(const MeasureOptions& options, const Catalogue& catalogue,
                      const PointCloud& body_cloud, const LandmarkSet& landmarks,
                      Progress* progress = nullptr);

// The girth plane (point, unit normal; body frame, mm) of a section_hull
// measurement for these landmarks; the same rules as GirthPlaneOf in
// oracle/truth. InputError when a landmark is missing or the plane is
// degenerate.
std::pair<Eigen::Vector3d, Eigen::Vector3d> GirthPlane(const MeasurementDef& measurement,
                                                       const LandmarkSet& landmarks);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_MEASURE_H_
