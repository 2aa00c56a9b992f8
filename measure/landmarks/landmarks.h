// Datum points (landmarks) of a person, found automatically on a cleaned,
// body-framed scan, and the tailor's override file.
//
// Names are the catalogue's (measure/catalogue/catalogue.json), with paired
// landmarks expanded to <name>_left / <name>_right (the person's own sides;
// right is +x in the body frame). Definitions: docs/measurements.md; the
// detection method of each point: docs/landmarks.md.
//
// Input: the cleaned cloud of scanners/clean (body frame: mm, +z up, soles on
// z = 0, facing +y), #P x 3, normals used when present. A person standing in
// an A- or T-pose; holes from occlusion (armpits, crotch) are expected.
// Output: one Landmark per name the detector could place. A point it cannot
// place is listed in `missing` with the reason, never guessed silently; a
// point it placed with doubt carries flags and a lower confidence.
// Failure: InputError when the cloud cannot be a standing person (too few
// points, no legs/arms/head found); never aborts.
#ifndef BESPOKE_MEASURE_LANDMARKS_LANDMARKS_H_
#define BESPOKE_MEASURE_LANDMARKS_LANDMARKS_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "scanners/core/progress.h"
#include "scanners/core/types.h"

namespace bespoke {

struct Landmark {
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();  // body frame, on (or next to) the skin
  double confidence = 1.0;                                // 0..1; < 0.5 means "check this point"
  std::vector<std::string> flags;  // e.g. "in_hole", "arm_touching_torso", "override"
  std::string method;              // short tag of how it was found, e.g. "slice_width_min"
};

// The body part a cloud point belongs to, from the geodesic structure over
// the scan's surface (docs/landmarks.md, "Structure"): an arm resting on the
// trunk is still an arm. kNone: a stray piece away from the body.
enum class ScanPart : signed char { kTrunk = 0, kArmRight, kArmLeft, kLegRight, kLegLeft, kNone };

struct LandmarkSet {
  std::map<std::string, Landmark> points;      // catalogue names, paired ones expanded
  std::map<std::string, std::string> missing;  // name -> why it could not be placed
  // Per row of the cloud the set was detected on (#P), its body part; empty
  // when the structure failed or the points came from elsewhere (a file).
  std::vector<ScanPart> parts;
  bool Has(const std::string& name) const { return points.count(name) > 0; }
  // InputError naming the landmark (and the reason when it is missing).
  const Landmark& At(const std::string& name) const;
};

struct LandmarkOptions {
  double slice_step_mm = 5.0;            // default 5 mm: spacing of the horizontal slices profiled
  double slice_half_thickness_mm = 4.0;  // default 4 mm: points within this of a slice's plane
  // Landmark names to find (default empty = every catalogue landmark); lets
  // a caller that needs a few points skip the rest.
  std::vector<std::string> only;
  void Check() const;  // InputError when out of range
};

// Finds every catalogue landmark it can on `cloud` (body frame, mm).
LandmarkSet DetectLandmarks(const LandmarkOptions& options, const PointCloud& cloud,
                            Progress* progress = nullptr);

// The body part of every point of `cloud` (body frame, mm), as
// DetectLandmarks finds them; empty when the structure fails (no two feet).
// Never throws.
std::vector<ScanPart> FindBodyParts(const PointCloud& cloud);

// The override file a tailor writes to correct points:
//   { "frame": "body" | "scan", "units": "mm",
//     "landmarks": { "shoulder_right": [x, y, z], ... } }
// "frame": "scan" (the default when absent) means the input scan's own frame
// and units as stored in the file (what a viewer shows); "body" means the
// cleaned cloud's body frame in mm. A measurements or truth document
// (docs/contracts.md) is accepted as an override file too.
struct LandmarkOverrides {
  std::string frame = "scan";  // "scan" or "body"
  std::string units = "mm";    // unit of the coordinates: "mm", "cm", "dm" or "m"
  // As written in the file, in `units` (ApplyLandmarkOverrides converts).
  std::map<std::string, Eigen::Vector3d> points;
};
// InputError naming the file for unreadable JSON, an unknown landmark name,
// a non-finite or malformed coordinate, or an unknown frame/unit.
LandmarkOverrides ReadLandmarkOverrides(const std::filesystem::path& file);

// Replaces (or adds) the overridden points in `set`, mapped to the body
// frame (mm) with body_from_scan when the overrides are in the scan frame
// (body_from_scan then maps the file's coordinates, already converted to
// mm, to the body frame). Overridden points get confidence 1 and the flag
// "override"; they are removed from `missing`.
void ApplyLandmarkOverrides(const LandmarkOverrides& overrides,
                            const Eigen::Isometry3d& body_from_scan, LandmarkSet* set);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_LANDMARKS_LANDMARKS_H_
