#include "oracle/makehuman/makehuman_body.h"

#include <algorithm>
#include <cmath>

#include "oracle/makehuman/makehuman_landmarks.h"
#include "oracle/makehuman/makehuman_population.h"
#include "oracle/makehuman/makehuman_random.h"
#include "oracle/truth/defined_landmarks.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

void CheckRange(const std::optional<double>& v, const char* name, double lo, double hi) {
  if (v && !(*v >= lo && *v <= hi))
    throw InputError(std::string("makehuman: ") + name + " = " + std::to_string(*v) +
                     " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// Weights of the three corners min/average/max for a value in [0, 1].
struct Corners {
  double min, average, max;
};
Corners ThreeCorners(double v) {
  const double lo = std::max(0.0, 1 - 2 * v), hi = std::max(0.0, 2 * v - 1);
  return {lo, 1 - lo - hi, hi};
}

const char* kCornerNames[3] = {"min", "average", "max"};

double Corner(const Corners& c, int i) { return i == 0 ? c.min : i == 1 ? c.average : c.max; }

}  // namespace

const std::vector<std::string>& MakeHumanMeasureNames() {
  static const std::vector<std::string> names = {
      "bust-circ",       "underbust-circ",  "waist-circ",      "hips-circ",
      "neck-circ",       "upperarm-circ",   "wrist-circ",      "thigh-circ",
      "knee-circ",       "calf-circ",       "ankle-circ",      "napetowaist-dist",
      "waisttohip-dist", "shoulder-dist",   "frontchest-dist", "upperarm-length",
      "lowerarm-length", "upperleg-height", "lowerleg-height", "neck-height"};
  return names;
}

void MakeHumanBodyOptions::Check() const {
  CheckRange(gender, "gender", 0, 1);
  CheckRange(age_years, "age_years", 18, 90);
  CheckRange(muscle, "muscle", 0, 1);
  CheckRange(weight, "weight", 0, 1);
  CheckRange(proportions, "proportions", 0, 1);
  CheckRange(stature_mm, "stature_mm", 1400, 2100);
  CheckRange(cup, "cup", 0, 1);
  CheckRange(firmness, "firmness", 0, 1);
  for (const auto* race : {&african, &asian, &caucasian}) CheckRange(*race, "ethnic weight", 0, 1);
  if (african && asian && caucasian && *african + *asian + *caucasian <= 0)
    throw InputError("makehuman: the ethnic weights african, asian, caucasian are all 0");
  if (!(measure_spread >= 0 && measure_spread <= 1))
    throw InputError("makehuman: measure_spread must be in [0, 1]");
  const auto& populations = MakeHumanPopulationNames();
  if (std::find(populations.begin(), populations.end(), population) == populations.end())
    throw InputError("makehuman: unknown population '" + population + "' (default, full)");
  CheckMakeHumanShape(shape);
  posture.Check();
  const auto& known = MakeHumanMeasureNames();
  for (const auto& [name, value] : measure) {
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw InputError("makehuman: unknown measure target '" + name + "'");
    if (!(value >= -1 && value <= 1))
      throw InputError("makehuman: measure." + name + " must be in [-1, 1]");
  }
}

void MakeHumanBodyOptions::Set(const std::string& name, double value) {
  const std::map<std::string, std::optional<double>*> fields = {
      {"gender", &gender}, {"age_years", &age_years},     {"muscle", &muscle},
      {"weight", &weight}, {"proportions", &proportions}, {"stature_mm", &stature_mm},
      {"cup", &cup},       {"firmness", &firmness},       {"african", &african},
      {"asian", &asian},   {"caucasian", &caucasian}};
  if (const auto it = fields.find(name); it != fields.end()) {
    *it->second = value;
  } else if (name == "measure_spread") {
    measure_spread = value;
  } else if (name == "defined_landmarks") {
    defined_landmarks = value != 0;
  } else if (name == "seed") {
    if (!(value >= 0) || value != std::floor(value)) throw InputError("makehuman: bad seed");
    seed = static_cast<std::uint64_t>(value);
  } else if (name.rfind("measure.", 0) == 0) {
    measure[name.substr(8)] = value;
  } else if (name.rfind("shape.", 0) == 0) {
    shape[name.substr(6)] = value;
  } else {
    throw InputError(
        "makehuman: unknown parameter '" + name +
        "' (gender, age_years, muscle, weight, proportions, stature_mm, cup, "
        "firmness, african, asian, caucasian, measure_spread, measure.<name>, shape.<name>)");
  }
}

MakeHumanParameters MakeHumanDraw(const MakeHumanBodyOptions& o) {
  o.Check();
  if (o.population == "full") return MakeHumanDrawFull(o);
  MakeHumanRandom random(o.seed);
  MakeHumanParameters p;
  // Every draw happens whether or not it is overridden, so overriding one
  // value does not change the others.
  const bool female = random.Uniform(0, 1) < 0.5;
  const double gender = female ? random.Uniform(0, 0.1) : random.Uniform(0.9, 1);
  p.gender = o.gender.value_or(gender);
  p.age_years = o.age_years.value_or(random.Uniform(25, 65));
  p.muscle = o.muscle.value_or(random.Uniform(0.25, 0.8));
  p.weight = o.weight.value_or(random.Uniform(0.1, 0.9));
  p.proportions = o.proportions.value_or(random.Uniform(0.3, 1.0));
  const double stature = p.gender < 0.5 ? std::clamp(random.Normal(1640, 65), 1500.0, 1800.0)
                                        : std::clamp(random.Normal(1775, 70), 1620.0, 1950.0);
  p.stature_mm = o.stature_mm.value_or(stature);
  p.cup = o.cup.value_or(random.Uniform(0.25, 0.85));
  p.firmness = o.firmness.value_or(random.Uniform(0.3, 0.8));
  DrawMakeHumanEthnicWeights(o, &random, &p);
  for (const std::string& name : MakeHumanMeasureNames()) {
    const double drawn = random.Uniform(-o.measure_spread, o.measure_spread);
    const auto it = o.measure.find(name);
    p.measure[name] = it != o.measure.end() ? it->second : drawn;
  }
  p.shape = o.shape;
  return p;
}

std::map<std::string, double> MakeHumanTargetWeights(const MakeHumanParameters& p,
                                                     double height_weight) {
  std::map<std::string, double> w;
  auto add = [&w](const std::string& name, double weight) {
    if (weight > 1e-9) w[name] += weight;
  };
  const double genders[2] = {1 - p.gender, p.gender};
  const char* gender_names[2] = {"female", "male"};
  const double old = std::clamp((p.age_years - 25) / 65, 0.0, 1.0);
  const double ages[2] = {1 - old, old};
  const char* age_names[2] = {"young", "old"};
  const Corners muscle = ThreeCorners(p.muscle), weight = ThreeCorners(p.weight);
  const Corners cup = ThreeCorners(p.cup), firmness = ThreeCorners(p.firmness);
  const std::pair<const char*, double> races[3] = {
      {"african", p.african}, {"asian", p.asian}, {"caucasian", p.caucasian}};
  for (int g = 0; g < 2; ++g) {
    const std::string gn = gender_names[g];
    for (int a = 0; a < 2; ++a)
      for (const auto& [race, rw] : races)
        add("macrodetails/" + std::string(race) + "-" + gn + "-" + age_names[a] + ".target",
            rw * genders[g] * ages[a]);
    for (int m = 0; m < 3; ++m)
      for (int k = 0; k < 3; ++k) {
        const std::string mw =
            std::string(kCornerNames[m]) + "muscle-" + kCornerNames[k] + "weight";
        const double gmw = genders[g] * Corner(muscle, m) * Corner(weight, k);
        for (int a = 0; a < 2; ++a)
          if (!(m == 1 && k == 1))  // the average-average targets are empty files
            add("macrodetails/universal-" + gn + "-" + age_names[a] + "-" + mw + ".target",
                gmw * ages[a]);
        // Height and proportions exist for young adults only; applied at every age.
        const std::string young = gn + "-young-" + mw;
        add("macrodetails/height/" + young + (height_weight > 0 ? "-maxheight" : "-minheight") +
                ".target",
            gmw * std::abs(height_weight));
        add("macrodetails/proportions/" + young + "-idealproportions.target",
            gmw * std::max(0.0, 2 * p.proportions - 1));
        add("macrodetails/proportions/" + young + "-uncommonproportions.target",
            gmw * std::max(0.0, 1 - 2 * p.proportions));
        if (g == 0)  // breasts: female targets only
          for (int a = 0; a < 2; ++a)
            for (int c = 0; c < 3; ++c)
              for (int f = 0; f < 3; ++f)
                if (!(c == 1 && f == 1))  // no file for average cup and firmness
                  add("breast/female-" + std::string(age_names[a]) + "-" + mw + "-" +
                          kCornerNames[c] + "cup-" + kCornerNames[f] + "firmness.target",
                      gmw * ages[a] * Corner(cup, c) * Corner(firmness, f));
      }
  }
  for (const auto& [name, value] : p.measure)
    add("measure/measure-" + name + (value > 0 ? "-incr" : "-decr") + ".target", std::abs(value));
  AddMakeHumanShapeWeights(p.shape, &w);
  return w;
}

namespace {

// Stature (MakeHuman units) of base + d0 + h * d1 for the vertices' heights.
double StatureAt(const Eigen::VectorXd& y0, const Eigen::VectorXd& dy, double h) {
  const Eigen::VectorXd y = y0 + h * dy;
  return y.maxCoeff() - y.minCoeff();
}

// The height weight in [-1, 1] giving `stature_dm`, by bisection on each
// side (stature is monotone in the weight for these targets). Beyond the
// targets' reach: InputError, or with `clamp` the weight +-1 (and
// *stature_dm the stature it gives).
double SolveHeightWeight(MakeHumanModel* model, const MakeHumanParameters& p, double* stature_dm_io,
                         bool clamp) {
  const double stature_dm = *stature_dm_io;
  const Eigen::VectorXd y0 = model->Morph(MakeHumanTargetWeights(p, 0)).vertices.col(1);
  const Eigen::VectorXd up = model->Morph(MakeHumanTargetWeights(p, 1)).vertices.col(1) - y0;
  const Eigen::VectorXd down = y0 - model->Morph(MakeHumanTargetWeights(p, -1)).vertices.col(1);
  const double s0 = StatureAt(y0, up, 0);
  const bool taller = stature_dm > s0;
  const Eigen::VectorXd& d = taller ? up : down;
  const double sign = taller ? 1 : -1;
  double lo = 0, hi = 1;
  if ((StatureAt(y0, sign * d, 1) - stature_dm) * sign < 0) {
    if (clamp) {
      *stature_dm_io = StatureAt(y0, sign * d, 1);
      return sign;
    }
    throw InputError("makehuman: stature " + std::to_string(stature_dm * 100) +
                     " mm is beyond the height targets' range for these parameters");
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    if ((StatureAt(y0, sign * d, mid) - stature_dm) * sign < 0)
      lo = mid;
    else
      hi = mid;
  }
  return sign * 0.5 * (lo + hi);
}

// The crown: the body's highest vertex. Not a fixed vertex of the table:
// the top of the head moves among neighbouring vertices as the head's shape
// changes (the table's vertex 881 was up to 0.35 mm lower than the top on
// seeds 1-10), and stature is defined by the top.
SurfacePoint HighestVertex(const TriangleMesh& mesh) {
  Eigen::Index top = 0;
  mesh.vertices.col(2).maxCoeff(&top);
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces(f, k) == top) {
        SurfacePoint p;
        p.face = static_cast<int>(f);
        p.barycentric[k] = 1;
        return p;
      }
  throw InternalError("makehuman: the highest vertex is not used by a face");
}

// The rest positions of the bone-carried datum points
// (MakeHumanBoneCarriedLandmarks): their table vertices on the rest skin.
std::map<std::string, Eigen::Vector3d> BoneCarriedRestPositions(const TriangleMesh& rest) {
  std::map<std::string, Eigen::Vector3d> out;
  for (const BoneCarriedLandmark& l : MakeHumanBoneCarriedLandmarks())
    for (const MakeHumanLandmark& t : MakeHumanLandmarkTable())
      if (std::string(t.name) == l.name) out[l.name] = rest.vertices.row(t.vertex).transpose();
  return out;
}

// The bone-carried datum points of a posed body: each rest position moved
// by its bone, then the posed skin's closest point. Returns the largest
// distance from a moved point to the skin (mm).
double CarryBonyLandmarks(const MakeHumanRig& rig, const PoseResult& pose,
                          const std::map<std::string, Eigen::Vector3d>& rest, Body* body) {
  double largest_mm = 0;
  for (const BoneCarriedLandmark& l : MakeHumanBoneCarriedLandmarks()) {
    const Eigen::Affine3d& g = pose.bone_from_rest.at(static_cast<size_t>(rig.BoneIndex(l.bone)));
    const Eigen::Vector3d moved = g * rest.at(l.name);
    const SurfacePoint on_skin = ClosestSurfacePoint(body->mesh, moved);
    largest_mm = std::max(largest_mm, (PositionOf(body->mesh, on_skin) - moved).norm());
    body->landmarks[l.name] = on_skin;
  }
  return largest_mm;
}

}  // namespace

Body GenerateMakeHumanBody(const MakeHumanBodyOptions& options, MakeHumanModel* model) {
  MakeHumanParameters p = MakeHumanDraw(options);
  double stature_dm = p.stature_mm / 100;
  const double height_weight =
      SolveHeightWeight(model, p, &stature_dm, /*clamp=*/!options.stature_mm.has_value());
  const bool clamped = stature_dm != p.stature_mm / 100;
  if (clamped) p.stature_mm = stature_dm * 100;
  Body body;
  body.model = "makehuman";
  const Eigen::MatrixX3d all = model->MorphAll(MakeHumanTargetWeights(p, height_weight));
  body.mesh.vertices = model->SkinRows(all);
  body.mesh.faces = model->base_body().faces;
  const Eigen::Affine3d body_from_mh = MakeHumanModel::BodyFromMakeHuman();
  TransformInPlace(body_from_mh, &body.mesh);
  PoseResult pose;
  std::map<std::string, Eigen::Vector3d> bone_carried_rest;
  if (!options.posture.empty()) {
    const MakeHumanRig& rig = model->Rig();
    std::map<std::string, Eigen::Vector3d> joints = RigJoints(rig, all);
    for (auto& [name, joint] : joints) joint = body_from_mh * joint;
    bone_carried_rest = BoneCarriedRestPositions(body.mesh);
    pose = PoseMakeHumanSkin(rig, body.mesh, joints, options.posture);
    body.mesh.vertices = pose.vertices;
  }
  body.limbs = RigLimbs(model->Rig());
  body.landmarks = MakeHumanLandmarkPoints(body.mesh);
  double bone_carried_off_skin_mm = 0;
  if (!options.posture.empty())
    bone_carried_off_skin_mm = CarryBonyLandmarks(model->Rig(), pose, bone_carried_rest, &body);
  PlaceOnFloorBetweenAnkles(&body);
  body.landmarks["crown"] = HighestVertex(body.mesh);
  DefinedLevels levels;
  if (options.defined_landmarks) {
    // The mid-sagittal seam: skin vertices on x = 0 of the symmetric base.
    std::vector<int> seam;
    const Eigen::MatrixX3d& base = model->base_body().vertices;
    for (Eigen::Index v = 0; v < base.rows(); ++v)
      if (std::abs(base(v, 0)) < 1e-5) seam.push_back(static_cast<int>(v));
    levels = PlaceDefinedLandmarks(DefinedLandmarkOptions(), seam, &body);
  }
  auto& q = body.parameters;
  q["seed"] = static_cast<double>(options.seed);
  q["gender"] = p.gender, q["age_years"] = p.age_years, q["muscle"] = p.muscle;
  q["weight"] = p.weight, q["proportions"] = p.proportions, q["stature_mm"] = p.stature_mm;
  q["cup"] = p.cup, q["firmness"] = p.firmness, q["african"] = p.african;
  q["asian"] = p.asian, q["caucasian"] = p.caucasian, q["height_weight"] = height_weight;
  q["measure_spread"] = options.measure_spread;
  for (const auto& [name, value] : p.measure) q["measure." + name] = value;
  for (const auto& [name, value] : p.shape) q["shape." + name] = value;
  if (options.population == "full") {
    q["population_full"] = 1;
    q["hard_case"] = p.hard_case;
  }
  if (clamped) q["stature_clamped"] = 1;
  q["defined_landmarks"] = options.defined_landmarks ? 1 : 0;
  if (options.defined_landmarks) {
    q["level.hip_mm"] = levels.hip_mm, q["level.waist_mm"] = levels.waist_mm;
    q["level.middle_hip_mm"] = levels.middle_hip_mm;
    q["level.under_bust_mm"] = levels.under_bust_mm;
    q["level.calf_right_mm"] = levels.calf_right_mm, q["level.calf_left_mm"] = levels.calf_left_mm;
  }
  if (!options.posture.empty()) {
    for (const auto& [name, value] : pose.reached) q["pose." + name] = value;
    for (const auto& [name, value] : pose.rest) q["pose.rest_" + name] = value;
    q["pose.new_self_intersections"] = pose.new_self_intersections;
    q["pose.bone_carried_off_skin_mm"] = bone_carried_off_skin_mm;
    q["pose.arms_stopped_at_contact"] = pose.arms_stopped ? 1 : 0;
    q["pose.legs_stopped_at_contact"] = pose.legs_stopped ? 1 : 0;
  }
  return body;
}

}  // namespace bespoke
