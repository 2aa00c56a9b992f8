// Diverse adult MakeHuman bodies from a seed, in the body frame, with their
// datum points known exactly (fixed points of the base topology,
// oracle/makehuman/makehuman_landmarks.h).
//
// The blend (our reading of the target folders' names; docs/oracle.md,
// "MakeHuman bodies", has the details): the macro parameters are
//   gender g (0 female .. 1 male), age in years (18 .. 90; the
//   targets' young end is 25), muscle m and
//   weight w (0 .. 1, 0.5 average), proportions p (0 uncommon, 0.5 neutral,
//   1 ideal), ethnic mix (african, asian, caucasian; normalised to sum 1),
//   breast cup and firmness (0 .. 1, 0.5 average; women only),
// each turned into weights of its folder's corner targets by linear
// interpolation (e.g. m = 0.25 -> minmuscle 0.5, averagemuscle 0.5), and a
// target named a-b-c gets the product of its parts' weights:
//   macrodetails/<race>-<gender>-<young|old>           race x gender x age
//   macrodetails/universal-<gender>-<age>-<m>muscle-<w>weight
//   macrodetails/height/<gender>-young-<m>-<w>-<max|min>height
//   macrodetails/proportions/<gender>-young-<m>-<w>-<ideal|uncommon>proportions
//   breast/female-<age>-<m>-<w>-<cup>cup-<firmness>firmness
// plus measure/measure-<name>-<incr|decr> with weight |value| for each
// measure value in [-1, 1]. Age interpolates young (25 years) to old (90).
// The height weight is not drawn: it is solved (bisection) so that the body's
// stature equals stature_mm.
// Units and frame: the result is in mm in the body frame (docs/contracts.md):
// soles on z = 0, facing +y, origin midway between the ankles (mean of the
// four malleoli landmarks) in x and y.
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_BODY_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_BODY_H_

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "oracle/body/body.h"
#include "oracle/makehuman/makehuman_model.h"
#include "oracle/makehuman/makehuman_pose.h"

namespace bespoke {

struct MakeHumanBodyOptions {
  // Seed of the draws (any value; the same seed gives the same body).
  std::uint64_t seed = 1;
  // Population the draws come from: "default" (MakeHumanDraw's ranges) or
  // "full" (the whole range, hard cases included; makehuman_population.h).
  std::string population = "default";
  // Values left empty are drawn from the seed (ranges in MakeHumanDraw below);
  // set ones override the draw.
  std::optional<double> gender;                     // 0 female .. 1 male
  std::optional<double> age_years;                  // 18 .. 90 (targets: 25 and 90)
  std::optional<double> muscle;                     // 0 .. 1
  std::optional<double> weight;                     // 0 .. 1
  std::optional<double> proportions;                // 0 .. 1
  std::optional<double> stature_mm;                 // 1400 .. 2100, reached by the height targets
  std::optional<double> cup;                        // 0 .. 1
  std::optional<double> firmness;                   // 0 .. 1
  std::optional<double> african, asian, caucasian;  // >= 0, not all 0
  // measure/ target values, by name ("waist-circ", "napetowaist-dist", ...),
  // each in [-1, 1]; names not set are drawn from [-measure_spread, measure_spread].
  std::map<std::string, double> measure;
  double measure_spread = 0.3;  // default 0.3; 0 disables the measure draws
  // Shape targets by name (makehuman_population.h: "stomach-pregnant",
  // "bodyshape.fem-apple", ...), each in [-1, 1] (body shapes 0 .. 1); names
  // not set are drawn by the "full" population, 0 in the default one.
  std::map<std::string, double> shape;
  // The posture (makehuman_pose.h); empty: MakeHuman's rest pose.
  MakeHumanPosture posture;
  // true (default): the datum points the catalogue defines by a level or an
  // extreme (waist, hip, middle hip, under-bust, crotch, calf) are placed by
  // that definition on the (posed) mesh (oracle/truth/defined_landmarks.h);
  // false: every point is the fixed vertex of the table.
  bool defined_landmarks = true;

  // InputError naming the value when one is out of range.
  void Check() const;
  // Sets a value by name: the fields above ("gender", "age_years", ...,
  // "measure_spread"), "measure.<name>" (e.g. "measure.waist-circ") or
  // "shape.<name>" (e.g. "shape.stomach-pregnant").
  // InputError for unknown names. Lets the CLI take --param name=value.
  void Set(const std::string& name, double value);
};

// The measure/ targets drawn by default (names without "measure-" and
// "-incr/-decr").
const std::vector<std::string>& MakeHumanMeasureNames();

// The values used for a body: the options with every empty value drawn.
struct MakeHumanParameters {
  double gender = 0, age_years = 25, muscle = 0.5, weight = 0.5, proportions = 0.5;
  double stature_mm = 1650, cup = 0.5, firmness = 0.5;
  double african = 1.0 / 3, asian = 1.0 / 3, caucasian = 1.0 / 3;
  std::map<std::string, double> measure;
  std::map<std::string, double> shape;  // shape targets (makehuman_population.h)
  int hard_case = 0;                    // 0 none, else 1 + index in MakeHumanHardCases()
};
MakeHumanParameters MakeHumanDraw(const MakeHumanBodyOptions& options);

// Target weights (file name relative to targets/ -> weight) for the
// parameters, with the given height weight (-1 .. 1).
std::map<std::string, double> MakeHumanTargetWeights(const MakeHumanParameters& parameters,
                                                     double height_weight);

// Generates the body: model "makehuman", posed by options.posture (the
// datum points move with the skin: they are surface points of the same
// topology), landmarks from the fixed table
// (except the crown: the body's highest vertex, so stature = crown height),
// parameters = every value used (and "seed", "height_weight",
// "stature_clamped" = 1 when a drawn stature was beyond the height targets'
// reach and the nearest reachable one was used; "pose.<quantity>" reached
// and "pose.rest_<quantity>" of the rest pose, "pose.new_self_intersections",
// "pose.arms_stopped_at_contact", "pose.legs_stopped_at_contact" when posed).
// InputError for bad options, a stature set in the options that the height
// targets cannot reach (beyond weight +-1), or missing/malformed data.
Body GenerateMakeHumanBody(const MakeHumanBodyOptions& options, MakeHumanModel* model);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_BODY_H_
