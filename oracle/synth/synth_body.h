// One test subject's body from a model name, a seed and named parameters:
// the common front of `bespoke synth-body`, `bespoke synth-set` and
// `bespoke accuracy`, so the same seed gives the same body everywhere.
//
//   model "parametric": the built-in body (oracle/body/parametric_body.h);
//     seed 0 is the average body, seed N > 0 draws sex, stature, build and
//     proportions (SeededOptions, from `population`); `params` then override single sizes by
//     field name (ParametricBodyOptions::Set, e.g. "waist_girth_mm",
//     "arm_angle_deg"). Its shoulder, axilla and thigh points by MakeHuman's
//     rules (rule_landmarks.h), its levels by definition (defined_landmarks.h).
//   model "makehuman": MakeHuman CC0 data from `makehuman_dir` (default
//     $BESPOKE_SHARED_DIR/data/bodies/makehuman, else ../shared/...);
//     `params` by MakeHumanBodyOptions::Set name ("gender", "weight",
//     "measure.waist-circ", "shape.stomach-pregnant", ...); `population`
//     as MakeHumanBodyOptions::population.
// Output: a Body in the body frame (mm) with its datum points.
// Failure: InputError for an unknown model, a malformed "name=value", an
// unknown parameter name or value out of range, or missing MakeHuman data.
#ifndef BESPOKE_ORACLE_SYNTH_SYNTH_BODY_H_
#define BESPOKE_ORACLE_SYNTH_SYNTH_BODY_H_

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "oracle/body/body.h"

namespace bespoke {

class MakeHumanModel;

struct SynthBodyOptions {
  std::string model = "parametric";    // default "parametric"; or "makehuman"
  std::uint64_t seed = 1;              // default 1
  std::string population = "default";  // "default" (everyday spread) or "full" (whole range)
  // Posture name (oracle/makehuman/makehuman_pose.h, e.g. "arms-5",
  // "arms-30+feet-40"); "" = the model's own pose. The parametric body takes
  // the arm and feet postures within its range (arms 15-90 deg).
  std::string posture;
  std::vector<std::string> params;      // "name=value" strings, applied after the seeded draw
  std::filesystem::path makehuman_dir;  // default empty = DefaultMakeHumanDir()
  // InputError for an unknown model or population, or a malformed param.
  void Check() const;
};

// $BESPOKE_SHARED_DIR/data/bodies/makehuman, or ../shared/data/bodies/makehuman.
std::filesystem::path DefaultMakeHumanDir();

// "name=value" -> (name, value); InputError for a malformed string.
std::pair<std::string, double> ParseNamedValue(const std::string& name_equals_value);

// Generates bodies for several seeds reusing the loaded MakeHuman data.
class SynthBodyGenerator {
 public:
  SynthBodyGenerator();
  ~SynthBodyGenerator();
  // Throws as described above. Not thread-safe.
  Body Generate(const SynthBodyOptions& options);

 private:
  std::unique_ptr<MakeHumanModel> makehuman_;
  std::filesystem::path makehuman_dir_;
};

// One body (loads MakeHuman data each call; use the generator for many).
Body GenerateSynthBody(const SynthBodyOptions& options);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SYNTH_SYNTH_BODY_H_
