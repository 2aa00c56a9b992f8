// The anatomical datum points of a parametric body placed by the rules the
// MakeHuman landmark table was made with (landmark_analysis.h), so both
// models' truths follow one definition per point. The construction puts
// these points where it builds them (parametric_body.cc: the shoulder point
// at the torso's side at shoulder height, 60-80 mm inside the deltoid's
// outer corner; the bust point at the end of the flat front of the bust
// ring; the axilla points at the armscye's corners; the thigh point at the
// back of the leg 2.5 % of stature below the crotch), which are not the
// catalogue's points as those rules read them.
//
// Points (both sides): shoulder (acromion: the shoulder cap's extreme in
// the outward-up diagonal), axilla_front / axilla_back (the deepest front /
// back concavities of the section a quarter of the way up from the armpit
// to the shoulder point) and thigh (the leg's lateral extreme 20 mm below
// the crotch). Other points keep the construction's: the side neck agrees
// with its rule; the rules of the back and front neck, elbow, wrist, knee and
// malleoli read the joints' heights, which this body has only from its
// construction's own levels; the armpit (the armscye's bottom on the
// torso's side) stays because the rule's saddle vertex sits on the arm's
// root, further out and higher, where the chest girth's "trunk free of the
// arms" would take in part of the arm; the bust point is the bust ring's
// (the rule's "most forward point below the armpit" is the belly on bodies
// whose belly reaches further forward than the bust). The trunk levels, calf
// and upper arm are placed by defined_landmarks.h afterwards, from these.
//
// Method: the rules need the joints (ParametricBodyDetails::joints) and the
// arms of the A-pose they are written for, so they run on the same body
// built with `rest_abduction_deg`; each point is carried to the body as its
// closest surface point. The torso and legs are the same at every arm
// abduction; a fold on the arm's root goes to the nearest skin of the
// raised arm; the shoulder point only up to `max_shoulder_abduction_deg`.
#ifndef BESPOKE_ORACLE_SYNTH_RULE_LANDMARKS_H_
#define BESPOKE_ORACLE_SYNTH_RULE_LANDMARKS_H_

#include "oracle/body/body.h"
#include "oracle/body/parametric_body.h"

namespace bespoke {

struct RuleLandmarkOptions {
  // Arm abduction the rules run at, deg; default 30 (the catalogue's A-pose,
  // the oracle's default posture); 15-40 (above 45 the acromion rule's
  // diagonal runs along the arm).
  double rest_abduction_deg = 30;
  // Largest arm abduction of the body whose shoulder point the rule places,
  // deg; default 45. The acromion rule reads the cap of a hanging arm; a
  // raised arm's root is rebuilt around a straight arm with no such cap,
  // and the A-pose's point carried to its nearest skin lies off the
  // shoulder's top. Above it the construction's point (the armscye's top
  // corner, where the raised arm's top leaves the torso) stays.
  double max_shoulder_abduction_deg = 45;
  // Throws InputError when out of range.
  void Check() const;
};

// Moves the points listed above on `body`, the parametric body that
// GenerateParametricBody built from `body_options` (the same options, seeded
// or not) with `details`; a body already at `rest_abduction_deg` serves as
// its own rest body (no second build). InputError when a rule finds nothing.
void PlaceRuleLandmarks(const RuleLandmarkOptions& options,
                        const ParametricBodyOptions& body_options,
                        const ParametricBodyDetails& details, Body* body);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SYNTH_RULE_LANDMARKS_H_
