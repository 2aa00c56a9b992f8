#include "oracle/makehuman/makehuman_landmarks.h"

#include "scanners/core/errors.h"

namespace bespoke {

const std::vector<MakeHumanLandmark>& MakeHumanLandmarkTable() {
  // Chosen by landmark_analysis.h's rules on the 24 bodies of seeds 1-24:
  // for each landmark the skin vertex with the smallest mean distance to
  // where the rule put it on each body (bust and under-bust: women only).
  // The comment after each row gives the rule and that mean distance.
  static const std::vector<MakeHumanLandmark> table = {
      // highest vertex; mean 2.9 max 34.5 mm. GenerateMakeHumanBody replaces it by each
      // body's highest vertex (this one was up to 0.35 mm lower than the top).
      {"crown", 881},
      // cervicale: back seam vertex at the height of the neck joint; mean 6.2 max 13.4 mm
      {"back_neck", 1496},
      // jugulare: most posterior front-seam vertex in the 80 mm below the neck joint; mean 3.2
      // max 12.5 mm
      {"front_neck", 815},
      // the corner between the side of the neck and the top of the shoulder in the coronal
      // section through the neck joint; mean 9.2 max 23.8 mm
      {"side_neck_right", 1503},
      {"side_neck_left", 8187},  // mirror of the right
      // acromion: the shoulder cap's extreme in the outward-up diagonal from the shoulder joint;
      // mean 0.8 max 18.4 mm
      {"shoulder_right", 1608},
      {"shoulder_left", 8280},  // mirror of the right
      // deepest front concavity of the trunk+arm section 1/4 of the way up from the armpit to
      // the shoulder point; mean 12.0 max 32.7 mm
      {"axilla_front_right", 1679},
      {"axilla_front_left", 8351},  // mirror of the right
      // deepest back concavity of the same section; mean 12.5 max 25.5 mm
      {"axilla_back_right", 3844},
      {"axilla_back_left", 10509},  // mirror of the right
      // saddle vertex where the horizontal section of the upper arm separates from the trunk's;
      // mean 8.8 max 21.4 mm
      {"armpit_right", 1664},
      {"armpit_left", 8336},  // mirror of the right
      // the nipple: the front-most vertex of the ring moved by breast/nipple-point targets; also
      // the women's most forward breast vertex; mean 13.2 max 31.6 mm
      {"bust_right", 1782},
      {"bust_left", 8454},  // mirror of the right
      // front seam at the under-bust fold (sharpest bend of the front profile through the bust
      // point), women; mean 11.1 max 23.7 mm
      {"under_bust", 4070},
      // front seam at the level of the smallest trunk girth between hip and under-bust; mean
      // 13.9 max 58.8 mm
      {"front_waist", 4069},
      // back seam at the waist level; mean 19.0 max 80.7 mm
      {"back_waist", 4045},
      // lateral extreme of the trunk section at the waist level; mean 15.8 max 60.4 mm
      {"side_waist_right", 4143},
      {"side_waist_left", 10786},  // mirror of the right
      // front seam midway between the hip and waist levels; mean 15.5 max 42.6 mm
      {"middle_hip_front", 4367},
      // back seam at the level of the most posterior point of the buttocks; mean 7.2 max 41.7 mm
      {"hip_back", 4223},
      // lateral extreme of the trunk section at the hip level (hands excluded); mean 17.9 max
      // 43.0 mm
      {"hip_right", 4296},
      {"hip_left", 10926},  // mirror of the right
      // lowest vertex of the mid-sagittal seam; mean 0.0 max 0.0 mm
      {"crotch", 4372},
      // outer extreme of the upper arm midway between the shoulder point and the elbow; mean 9.5
      // max 56.3 mm
      {"upper_arm_right", 1704},
      {"upper_arm_left", 8376},  // mirror of the right
      // olecranon: most posterior vertex of the arm's slab at the elbow joint; mean 2.5 max 11.2
      // mm
      {"elbow_right", 3374},
      {"elbow_left", 10042},  // mirror of the right
      // ulnar styloid: most posterior vertex of the forearm's slab at the wrist joint; mean 3.4
      // max 21.0 mm
      {"wrist_right", 3901},
      {"wrist_left", 10566},  // mirror of the right
      // lateral extreme of the leg section 20 mm below the crotch; mean 13.4 max 34.3 mm
      {"thigh_right", 4440},
      {"thigh_left", 11058},  // mirror of the right
      // mid-patella: most forward vertex of the leg at the knee joint's height; mean 12.9 max
      // 32.5 mm
      {"knee_right", 4624},
      {"knee_left", 11242},  // mirror of the right
      // most posterior vertex of the lower leg (30-90 % from ankle to knee); mean 19.8 max 44.4
      // mm
      {"calf_right", 4721},
      {"calf_left", 11339},  // mirror of the right
      // medial malleolus: medial extreme of the leg at the ankle joint's height; mean 3.5 max
      // 12.4 mm
      {"ankle_inside_right", 6341},
      {"ankle_inside_left", 12938},  // mirror of the right
      // lateral malleolus: lateral extreme of the leg at the ankle joint's height; mean 10.3 max
      // 22.4 mm
      {"ankle_outside_right", 6373},
      {"ankle_outside_left", 12970},  // mirror of the right
  };
  return table;
}

const std::vector<BoneCarriedLandmark>& MakeHumanBoneCarriedLandmarks() {
  // The acromion is the shoulder blade's (bone shoulder01); its skin vertex
  // 1608 weighs upperarm01 0.80, upperarm02 0.07, shoulder01 0.08, clavicle
  // 0.05 in default_weights.mhw.
  static const std::vector<BoneCarriedLandmark> table = {{"shoulder_right", "shoulder01.R"},
                                                         {"shoulder_left", "shoulder01.L"}};
  return table;
}

std::map<std::string, SurfacePoint> MakeHumanLandmarkPoints(const TriangleMesh& mesh) {
  // One face per vertex: the first face that uses it.
  std::vector<int> face_of(static_cast<std::size_t>(mesh.num_vertices()), -1);
  for (Eigen::Index f = mesh.num_faces() - 1; f >= 0; --f)
    for (int k = 0; k < 3; ++k)
      face_of[static_cast<std::size_t>(mesh.faces(f, k))] = static_cast<int>(f);
  std::map<std::string, SurfacePoint> points;
  for (const MakeHumanLandmark& l : MakeHumanLandmarkTable()) {
    BESPOKE_CHECK(l.vertex >= 0 && l.vertex < mesh.num_vertices() &&
                      face_of[static_cast<std::size_t>(l.vertex)] >= 0,
                  std::string("MakeHuman landmark ") + l.name + " is not a vertex of the skin");
    SurfacePoint p;
    p.face = face_of[static_cast<std::size_t>(l.vertex)];
    for (int k = 0; k < 3; ++k) p.barycentric[k] = mesh.faces(p.face, k) == l.vertex ? 1 : 0;
    points[l.name] = p;
  }
  return points;
}

void PlaceOnFloorBetweenAnkles(Body* body) {
  Eigen::Vector3d shift(0, 0, -body->mesh.vertices.col(2).minCoeff());
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  int count = 0;
  for (const char* name :
       {"ankle_inside_left", "ankle_inside_right", "ankle_outside_left", "ankle_outside_right"}) {
    const auto it = body->landmarks.find(name);
    if (it == body->landmarks.end()) continue;
    centre += PositionOf(body->mesh, it->second).head<2>();
    ++count;
  }
  if (count > 0) shift.head<2>() = -centre / count;
  body->mesh.vertices.rowwise() += shift.transpose();
}

}  // namespace bespoke
