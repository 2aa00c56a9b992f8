// Geometric rules that locate the datum points on a MakeHuman body: the
// analysis behind the fixed landmark table (makehuman_landmarks.h), kept so
// the choice can be re-run and checked on any generated body.
//
// Input: the skin mesh in the body frame (mm, +z up, facing +y, right = +x,
// soles on z = 0) and the centres of MakeHuman's joint helper groups in the
// same frame (MakeHumanModel::MorphWithJoints, names without "joint-", e.g.
// "r-elbow", "neck", "r-hand" (the wrist joint), "r-ankle").
// Output: per landmark (catalogue names, both sides; left = the right rule
// mirrored) the point the rule finds, the nearest skin vertex, and the rule
// in words. The rules (details in the .cc and docs/oracle.md):
//   crown           highest vertex
//   crotch          lowest vertex on the mid-sagittal seam (x = 0) above 30 % of stature
//   armpit          the saddle vertex of the height function where the horizontal
//                   section of the arm separates from the trunk's
//   shoulder        acromion: the shoulder cap's extreme vertex in the outward-up
//                   diagonal (45 deg) from the shoulder joint, near its coronal plane
//   back_neck       cervicale: back seam vertex at the height of the neck joint
//                   (MakeHuman's cervico-thoracic joint)
//   front_neck      jugulare: the most posterior front-seam vertex between the neck
//                   joint height - 80 mm and + 30 mm (the notch above the sternum)
//   side_neck       in the coronal section through the neck joint, the concave corner
//                   between the side of the neck and the top of the shoulder
//   axilla_front/back  deepest front/back concavity of the trunk-and-arm section a
//                   quarter of the way up from the armpit to the shoulder point
//   bust            most forward vertex of the chest between the armpit level and
//                   15 % of stature below it, 20-200 mm from the midline
//   under_bust      front seam vertex at the height of the under-bust fold (the most
//                   posterior point of the profile below the bust point)
//   waist (front, back, side)  level of the smallest trunk girth between the
//                   under-bust and the hip; seam vertices and the lateral extreme there
//   hip (back, side)  level of the most posterior point of the buttocks; back seam
//                   vertex and the trunk section's lateral extreme there
//   middle_hip_front front seam vertex midway between the hip and waist levels
//   thigh           lateral extreme of the leg section 20 mm below the crotch
//   knee            most forward vertex of the leg within 15 mm of the knee joint height
//   calf            most posterior vertex of the lower leg (30-90 % knee to ankle)
//   ankle_inside/outside  medial/lateral extreme of the leg within 12 mm of the
//                   ankle joint height (the malleoli)
//   elbow           most posterior vertex of the arm's slab around the elbow joint
//   wrist           most posterior vertex of the forearm's slab around the wrist joint
//   upper_arm       outer extreme of the arm's slab midway between shoulder and elbow
// Failure: InputError when a rule finds nothing (e.g. a mesh that is not a
// standing MakeHuman body).
#ifndef BESPOKE_ORACLE_MAKEHUMAN_LANDMARK_ANALYSIS_H_
#define BESPOKE_ORACLE_MAKEHUMAN_LANDMARK_ANALYSIS_H_

#include <map>
#include <string>

#include "scanners/core/types.h"

namespace bespoke {

struct AnalysedLandmark {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // where the rule puts it, mm
  int vertex = -1;                                     // nearest skin vertex
};

std::map<std::string, AnalysedLandmark> AnalyseMakeHumanLandmarks(
    const TriangleMesh& body_mesh, const std::map<std::string, Eigen::Vector3d>& joints);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_LANDMARK_ANALYSIS_H_
