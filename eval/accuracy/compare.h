// One subject's measurements compared with its truth, both as measurement
// documents (docs/contracts.md: "bespoke-measurements", values in mm). The
// truth is the oracle's exact one, or on real subjects a document of the
// reference values (no datum points, so no landmark errors).
//
// Measurements: for every measurement of the truth document with a value,
// measured - truth (mm); a measurement the measured document lacks (or gives
// no finite value for) is listed as missing, never guessed. Flags of both
// sides are kept.
//
// Landmarks: the error is the 3-D distance (mm) between the measured and
// the true datum point; for a point the catalogue defines by a level alone
// (LandmarkDef::level: calf, thigh) it is the distance along the body's up
// axis (mapped through body_from_scanner; with both documents in the
// scanner frame and no transform, the scanner's z), as that point's
// definition places it by its height only. Points are compared in one
// frame:
//   - "scanner": when the truth carries the scanner frame (the virtual
//     scanner's truth: "frame": "scanner", landmarks in the scanner frame)
//     and the measured document carries its "body_from_scanner" (the frame
//     found by cleaning), measured points are mapped back to the scanner
//     frame, so the error is the landmark's own error, free of any error of
//     the estimated body frame;
//   - "body": otherwise both documents' body-frame points are compared
//     directly ("landmarks_body" of a scanner truth); the error then
//     includes the difference between the two body frames.
// Failure: InputError naming `subject` for a document that is not a
// measurement document or has malformed values.
#ifndef BESPOKE_EVAL_ACCURACY_COMPARE_H_
#define BESPOKE_EVAL_ACCURACY_COMPARE_H_

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace bespoke {

struct MeasurementDifference {
  std::string name;
  std::string kind;  // "girth", "length", "height"
  double truth_mm = 0;
  double measured_mm = 0;    // NaN when missing
  double difference_mm = 0;  // measured - truth; NaN when missing
  bool missing = false;
  std::vector<std::string> flags;        // the measured document's flags
  std::vector<std::string> truth_flags;  // the truth's flags
};

struct LandmarkError {
  std::string name;
  Eigen::Vector3d truth_mm = Eigen::Vector3d::Zero();     // in `frame`
  Eigen::Vector3d measured_mm = Eigen::Vector3d::Zero();  // in `frame`; zero when missing
  double error_mm = 0;                                    // NaN when missing
  bool missing = false;
  bool height_only = false;  // a level's point: error_mm is the height difference
};

struct SubjectComparison {
  std::string subject;
  std::string landmark_frame;                       // "scanner" or "body" (see above)
  std::vector<MeasurementDifference> measurements;  // truth order
  std::vector<LandmarkError> landmarks;             // truth's landmarks, by name
};

SubjectComparison CompareDocuments(const nlohmann::json& measured, const nlohmann::json& truth,
                                   const std::string& subject);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_COMPARE_H_
