#include "oracle/makehuman/makehuman_pose.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "oracle/body/mesh_checks.h"
#include "oracle/makehuman/makehuman_model.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr double kDeg = M_PI / 180;

nlohmann::json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "cannot be read (the MakeHuman rig)");
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw InputError(file, std::string("is not valid JSON: ") + e.what());
  }
}

// Bones ordered so that parents come first.
std::vector<MakeHumanRig::Bone> OrderedBones(const nlohmann::json& bones,
                                             const std::filesystem::path& file) {
  std::map<std::string, std::string> parent_of;
  for (const auto& [name, bone] : bones.items())
    parent_of[name] = bone.at("parent").is_null() ? "" : bone.at("parent").get<std::string>();
  std::vector<MakeHumanRig::Bone> out;
  std::map<std::string, int> index;
  std::function<int(const std::string&, int)> add = [&](const std::string& name, int depth) {
    if (const auto it = index.find(name); it != index.end()) return it->second;
    if (depth > 200 || !parent_of.count(name))
      throw InputError(file, "bone '" + name + "' has a missing or cyclic parent");
    const std::string& p = parent_of[name];
    const int parent = p.empty() ? -1 : add(p, depth + 1);
    MakeHumanRig::Bone b;
    b.name = name;
    b.parent = parent;
    b.head = bones.at(name).at("head").get<std::string>();
    b.tail = bones.at(name).at("tail").get<std::string>();
    out.push_back(b);
    return index[name] = static_cast<int>(out.size()) - 1;
  };
  for (const auto& [name, p] : parent_of) add(name, 0);
  return out;
}

// Frontal-plane angle from the vertical of the line a -> b, with +x (the
// person's right) positive for `side` +1 and -x for side -1.
double FrontalAngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double side) {
  const Eigen::Vector3d d = b - a;
  return std::atan2(side * d.x(), -d.z()) / kDeg;
}

struct Chain {
  const MakeHumanRig& rig;
  const std::map<std::string, Eigen::Vector3d>& joints;
  // Global transform of every bone for the rotations.
  std::vector<Eigen::Affine3d> Globals(const std::map<int, Eigen::Matrix3d>& rotations) const {
    std::vector<Eigen::Affine3d> g(rig.bones.size(), Eigen::Affine3d::Identity());
    for (std::size_t i = 0; i < rig.bones.size(); ++i) {
      const MakeHumanRig::Bone& b = rig.bones[i];
      Eigen::Affine3d local = Eigen::Affine3d::Identity();
      if (const auto it = rotations.find(static_cast<int>(i)); it != rotations.end()) {
        const Eigen::Vector3d h = joints.at(b.head);
        local.linear() = it->second;
        local.translation() = h - it->second * h;
      }
      g[i] = (b.parent < 0 ? Eigen::Affine3d::Identity() : g[static_cast<std::size_t>(b.parent)]) *
             local;
    }
    return g;
  }
  // A joint's posed position: carried by the bone whose head it is.
  Eigen::Vector3d Joint(const std::vector<Eigen::Affine3d>& g, const std::string& bone) const {
    const int i = rig.BoneIndex(bone);
    return g[static_cast<std::size_t>(i)] * joints.at(rig.bones[static_cast<std::size_t>(i)].head);
  }
};

Eigen::Matrix3d Turn(double deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(deg * kDeg, axis).toRotationMatrix();
}

}  // namespace

int MakeHumanRig::BoneIndex(const std::string& name) const {
  for (std::size_t i = 0; i < bones.size(); ++i)
    if (bones[i].name == name) return static_cast<int>(i);
  throw InputError("makehuman rig: no bone '" + name + "'");
}

namespace {

// The limb of a bone by its name (e.g. "lowerarm02.R"); kTrunk for others.
BodyLimb LimbOfBone(const std::string& name) {
  const bool right = name.size() > 2 && name.compare(name.size() - 2, 2, ".R") == 0;
  const bool left = name.size() > 2 && name.compare(name.size() - 2, 2, ".L") == 0;
  if (!right && !left) return BodyLimb::kTrunk;
  const auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
  if (starts("upperarm") || starts("lowerarm") || starts("wrist") || starts("metacarpal") ||
      starts("finger"))
    return right ? BodyLimb::kArmRight : BodyLimb::kArmLeft;
  if (starts("upperleg") || starts("lowerleg") || starts("foot") || starts("toe"))
    return right ? BodyLimb::kLegRight : BodyLimb::kLegLeft;
  return BodyLimb::kTrunk;
}

}  // namespace

std::vector<BodyLimb> RigLimbs(const MakeHumanRig& rig) {
  std::vector<BodyLimb> bone_limb;
  for (const MakeHumanRig::Bone& bone : rig.bones) bone_limb.push_back(LimbOfBone(bone.name));
  std::vector<BodyLimb> limbs(rig.weights.size(), BodyLimb::kTrunk);
  for (std::size_t v = 0; v < rig.weights.size(); ++v) {
    double share[5] = {0, 0, 0, 0, 0};
    for (const auto& [bone, w] : rig.weights[v])
      share[static_cast<int>(bone_limb[static_cast<std::size_t>(bone)])] += w;
    for (int limb = 1; limb < 5; ++limb)
      if (share[limb] > 0.5) limbs[v] = static_cast<BodyLimb>(limb);
  }
  return limbs;
}

MakeHumanRig LoadMakeHumanRig(const std::filesystem::path& rig_dir, const MakeHumanModel& model) {
  const std::filesystem::path skel_file = rig_dir / "default.mhskel";
  const std::filesystem::path weights_file = rig_dir / "default_weights.mhw";
  const nlohmann::json skel = ReadJson(skel_file), weights = ReadJson(weights_file);
  MakeHumanRig rig;
  try {
    rig.bones = OrderedBones(skel.at("bones"), skel_file);
    for (const auto& [name, list] : skel.at("joints").items()) {
      std::vector<int> v = list.get<std::vector<int>>();
      for (int i : v)
        if (i < 0 || i >= model.num_base_vertices())
          throw InputError(skel_file, "joint '" + name + "' names vertex " + std::to_string(i) +
                                          " past base.obj's vertices");
      if (v.empty()) throw InputError(skel_file, "joint '" + name + "' has no vertices");
      rig.joint_vertices[name] = std::move(v);
    }
    for (const auto& b : rig.bones)
      if (!rig.joint_vertices.count(b.head) || !rig.joint_vertices.count(b.tail))
        throw InputError(skel_file, "bone '" + b.name + "' names a joint that is not listed");
    rig.weights.assign(model.base_body().vertices.rows(), {});
    for (const auto& [bone, list] : weights.at("weights").items()) {
      const int index = rig.BoneIndex(bone);
      for (const auto& pair : list) {
        const int base = pair.at(0).get<int>();
        const double w = pair.at(1).get<double>();
        if (base < 0 || base >= model.num_base_vertices() || !(w >= 0))
          throw InputError(weights_file, "bad weight for bone '" + bone + "'");
        const int v = model.BodyVertex(base);
        if (v >= 0 && w > 0) rig.weights[static_cast<std::size_t>(v)].emplace_back(index, w);
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(rig_dir, std::string("malformed MakeHuman rig: ") + e.what());
  }
  const int root = 0;  // parents come first
  for (auto& list : rig.weights) {
    double sum = 0;
    for (const auto& [b, w] : list) sum += w;
    if (sum <= 0) {
      list = {{root, 1.0}};
      continue;
    }
    for (auto& [b, w] : list) w /= sum;
  }
  return rig;
}

std::map<std::string, Eigen::Vector3d> RigJoints(const MakeHumanRig& rig,
                                                 const Eigen::MatrixX3d& all) {
  std::map<std::string, Eigen::Vector3d> joints;
  for (const auto& [name, list] : rig.joint_vertices) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : list) c += all.row(v).transpose();
    joints[name] = c / static_cast<double>(list.size());
  }
  return joints;
}

Eigen::MatrixX3d SkinWithRotations(const MakeHumanRig& rig, const Eigen::MatrixX3d& rest,
                                   const std::map<std::string, Eigen::Vector3d>& joints,
                                   const std::map<int, Eigen::Matrix3d>& rotations) {
  const std::vector<Eigen::Affine3d> g = Chain{rig, joints}.Globals(rotations);
  Eigen::MatrixX3d out(rest.rows(), 3);
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    const Eigen::Vector3d p = rest.row(v).transpose();
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    for (const auto& [b, w] : rig.weights[static_cast<std::size_t>(v)])
      q += w * (g[static_cast<std::size_t>(b)] * p);
    out.row(v) = q.transpose();
  }
  return out;
}

bool MakeHumanPosture::empty() const {
  return !arm_abduction_deg && !stance_mm && lean_deg == 0 && twist_deg == 0 && head_turn_deg == 0;
}

void MakeHumanPosture::Check() const {
  const auto range = [](const char* name, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi))
      throw InputError(std::string("posture: ") + name + " = " + std::to_string(v) +
                       " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  };
  if (arm_abduction_deg) range("arm_abduction_deg", *arm_abduction_deg, 0, 100);
  if (stance_mm) range("stance_mm", *stance_mm, 0, 600);
  range("lean_deg", lean_deg, -30, 30);
  range("twist_deg", twist_deg, -45, 45);
  range("head_turn_deg", head_turn_deg, -80, 80);
}

const std::vector<std::string>& MakeHumanPostureNames() {
  static const std::vector<std::string> names = {"rest",    "arms-5",  "arms-15",       "arms-30",
                                                 "arms-45", "arms-90", "feet-together", "feet-40",
                                                 "lean-5",  "twist-5", "head-turn"};
  return names;
}

MakeHumanPosture ParseMakeHumanPosture(const std::string& text) {
  MakeHumanPosture p;
  std::stringstream parts(text);
  std::string name;
  while (std::getline(parts, name, '+')) {
    if (name == "rest") {
    } else if (name.rfind("arms-", 0) == 0 &&
               std::set<std::string>{"5", "15", "30", "45", "90"}.count(name.substr(5))) {
      p.arm_abduction_deg = std::stod(name.substr(5));
    } else if (name == "feet-together") {
      p.stance_mm = 0;
    } else if (name == "feet-40") {
      p.stance_mm = 400;
    } else if (name == "lean-5") {
      p.lean_deg = 5;
    } else if (name == "twist-5") {
      p.twist_deg = 5;
    } else if (name == "head-turn") {
      p.head_turn_deg = 30;
    } else {
      std::string known;
      for (const std::string& n : MakeHumanPostureNames()) known += (known.empty() ? "" : ", ") + n;
      throw InputError("unknown posture '" + name + "' (known: " + known + "; join with +)");
    }
  }
  p.Check();
  return p;
}

namespace {

// Counts the face pairs of `vertices` that cross and are not in `rest`.
int NewCrossings(const TriangleMesh& skin, const Eigen::MatrixX3d& vertices,
                 const std::set<std::pair<int, int>>& rest) {
  TriangleMesh posed;
  posed.vertices = vertices;
  posed.faces = skin.faces;
  int count = 0;
  for (const auto& pair : SelfIntersectingFacePairs(posed)) count += rest.count(pair) ? 0 : 1;
  return count;
}

// Turns a symmetric pair of limbs (right bone, left bone) by `deg` about the
// front axis (positive: away from the body), plus `extra` rotations.
void AddLimbTurn(const MakeHumanRig& rig, const char* right, const char* left, double deg,
                 std::map<int, Eigen::Matrix3d>* rotations) {
  (*rotations)[rig.BoneIndex(right)] = Turn(-deg, Eigen::Vector3d::UnitY());
  (*rotations)[rig.BoneIndex(left)] = Turn(deg, Eigen::Vector3d::UnitY());
}

// The largest fraction t in [0, 1] of a move (rotations(t)) with no new
// crossing, by bisection to `step` of the move; 1 when the whole move is free.
double FreeFraction(const std::function<std::map<int, Eigen::Matrix3d>(double)>& rotations,
                    const MakeHumanRig& rig, const TriangleMesh& skin,
                    const std::map<std::string, Eigen::Vector3d>& joints,
                    const std::set<std::pair<int, int>>& rest, double step) {
  const auto free = [&](double t) {
    return NewCrossings(skin, SkinWithRotations(rig, skin.vertices, joints, rotations(t)), rest) ==
           0;
  };
  if (free(1)) return 1;
  double lo = 0, hi = 1;
  while (hi - lo > step) {
    const double mid = 0.5 * (lo + hi);
    (free(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

PoseResult PoseMakeHumanSkin(const MakeHumanRig& rig, const TriangleMesh& skin,
                             const std::map<std::string, Eigen::Vector3d>& joints,
                             const MakeHumanPosture& posture) {
  posture.Check();
  const Chain chain{rig, joints};
  PoseResult result;
  const auto arm_angle = [&](const std::vector<Eigen::Affine3d>& g) {
    return 0.5 * (FrontalAngleDeg(chain.Joint(g, "upperarm01.R"), chain.Joint(g, "wrist.R"), 1) +
                  FrontalAngleDeg(chain.Joint(g, "upperarm01.L"), chain.Joint(g, "wrist.L"), -1));
  };
  const auto stance = [&](const std::vector<Eigen::Affine3d>& g) {
    return (chain.Joint(g, "foot.R") - chain.Joint(g, "foot.L")).head<2>().norm();
  };
  const std::vector<Eigen::Affine3d> rest_g = chain.Globals({});
  result.rest["arm_abduction_deg"] = arm_angle(rest_g);
  result.rest["stance_mm"] = stance(rest_g);
  std::set<std::pair<int, int>> rest_pairs;
  if (!posture.empty()) {
    const auto pairs = SelfIntersectingFacePairs(skin);
    rest_pairs.insert(pairs.begin(), pairs.end());
  }
  std::map<int, Eigen::Matrix3d> rotations;
  const double contact_step = 0.25;  // degrees
  if (posture.stance_mm) {
    // Leg turn for the stance (stance grows with the turn): bisection.
    const auto legs = [&](double deg) {
      std::map<int, Eigen::Matrix3d> r = rotations;
      AddLimbTurn(rig, "upperleg01.R", "upperleg01.L", deg, &r);
      AddLimbTurn(rig, "foot.R", "foot.L", -deg, &r);  // the feet stay flat
      return r;
    };
    double lo = -25, hi = 40;
    for (int i = 0; i < 50; ++i) {
      const double mid = 0.5 * (lo + hi);
      (stance(chain.Globals(legs(mid))) < *posture.stance_mm ? lo : hi) = mid;
    }
    double deg = 0.5 * (lo + hi);
    if (posture.stop_at_contact && deg < 0) {
      const double t = FreeFraction([&](double f) { return legs(f * deg); }, rig, skin, joints,
                                    rest_pairs, contact_step / std::abs(deg));
      result.legs_stopped = t < 1;
      deg *= t;
    }
    rotations = legs(deg);
  }
  if (posture.arm_abduction_deg) {
    const auto arms = [&](double deg) {
      std::map<int, Eigen::Matrix3d> r = rotations;
      AddLimbTurn(rig, "upperarm01.R", "upperarm01.L", deg, &r);
      return r;
    };
    // The frontal angle is the turn about the front axis plus the rest angle
    // for each arm; the mean of both is exact for a symmetric body.
    double deg = *posture.arm_abduction_deg - arm_angle(chain.Globals(rotations));
    if (posture.stop_at_contact && deg < 0) {
      const double t = FreeFraction([&](double f) { return arms(f * deg); }, rig, skin, joints,
                                    rest_pairs, contact_step / std::abs(deg));
      result.arms_stopped = t < 1;
      deg *= t;
    }
    rotations = arms(deg);
  }
  for (const char* spine : {"spine05", "spine04", "spine03", "spine02", "spine01"}) {
    const Eigen::Matrix3d r = Turn(-posture.lean_deg / 5, Eigen::Vector3d::UnitX()) *
                              Turn(posture.twist_deg / 5, Eigen::Vector3d::UnitZ());
    if (posture.lean_deg != 0 || posture.twist_deg != 0) rotations[rig.BoneIndex(spine)] = r;
  }
  if (posture.head_turn_deg != 0)
    for (const char* neck : {"neck01", "neck02", "neck03", "head"})
      rotations[rig.BoneIndex(neck)] = Turn(posture.head_turn_deg / 4, Eigen::Vector3d::UnitZ());
  result.vertices = SkinWithRotations(rig, skin.vertices, joints, rotations);
  const std::vector<Eigen::Affine3d> g = chain.Globals(rotations);
  result.bone_from_rest = g;
  result.reached["arm_abduction_deg"] = arm_angle(g);
  result.reached["stance_mm"] = stance(g);
  result.reached["lean_deg"] = posture.lean_deg;
  result.reached["twist_deg"] = posture.twist_deg;
  result.reached["head_turn_deg"] = posture.head_turn_deg;
  if (!posture.empty())
    result.new_self_intersections = NewCrossings(skin, result.vertices, rest_pairs);
  return result;
}

}  // namespace bespoke
