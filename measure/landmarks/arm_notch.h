// The notch between an arm and the trunk in a horizontal section (internal
// to measure/landmarks).
//
// Below the armpit an arm beside the trunk shows in a section as its own
// lobe: apart from the trunk (a gap) or resting on it, where the scanner
// sees neither the arm's inner side nor the trunk's side and the outline
// has a deep crease in front and behind. Either way the section's depth
// (front-to-back extent), read outwards from the body's middle, falls
// between the trunk and the arm's lobe and rises again. Above the armpit
// the section tapers from the trunk into the shoulder without that dip.
// So the armpit of an arm that rests on the body lies where the notch ends,
// going up: where the arm leaves the trunk's outline is the elbow when the
// forearms bend forward, and the hollow of a heavy body's armpit is a hole.
#ifndef BESPOKE_MEASURE_LANDMARKS_ARM_NOTCH_H_
#define BESPOKE_MEASURE_LANDMARKS_ARM_NOTCH_H_

#include <Eigen/Core>
#include <vector>

namespace bespoke::landmarks {

struct ArmNotchOptions {
  double bin_mm = 5;              // default 5 mm: width of the depth profile's bins in x
  int min_bin_points = 3;         // default 3: a bin with fewer points has no depth
  double min_lobe_depth_mm = 40;  // default 40 mm: the arm's lobe is at least this deep
  // A section has a notch where a bin's depth is below this share of the
  // lesser of the deepest bins inside it (the trunk) and outside it (the
  // arm's lobe) (default 0.7: the crease of an arm resting on the trunk
  // leaves a third of the arm's depth or less; a shoulder's taper none).
  double max_ratio = 0.7;
};

struct ArmNotch {
  bool found = false;    // a bin below options.max_ratio
  double ratio = 1;      // the deepest notch's depth over its lobes' (1 when none)
  double x_mm = 0;       // body x of the deepest notch's bin centre (signed as the side)
  double y_mm = 0;       // middle of that bin's front-to-back extent
  double lobe_y_mm = 0;  // mean y of the points outside that bin (the arm's lobe)
};

// The deepest notch on side `sign` (+1 the person's right, +x; -1 the left)
// of a section: `rows` of `points` (#P x 3, body frame, mm), the section's
// points (the trunk and that arm; other limbs left out). Bins run outwards
// from x = 0; a notch is sought from a third of the side's width out, so
// the trunk's own curves near the middle never count, and only in a bin
// whose points reach the middle half of the lobe's depth (the crease runs
// deep; a bin holding only the outline's front or back, the other side
// unseen, lies out at the lobe's front or back).
ArmNotch FindArmNotch(const ArmNotchOptions& options, const Eigen::MatrixX3d& points,
                      const std::vector<int>& rows, int sign);

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_ARM_NOTCH_H_
