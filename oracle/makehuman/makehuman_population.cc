#include "oracle/makehuman/makehuman_population.h"

#include <algorithm>
#include <cmath>

#include "oracle/makehuman/makehuman_body.h"
#include "oracle/makehuman/makehuman_random.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// A shape value's files: folder/prefix + (incr|up) or (decr|down); `limb`
// adds the l- and r- files.
struct ShapeTarget {
  const char* name;
  const char* folder;
  const char* positive;  // suffix of the positive file, e.g. "-incr"
  const char* negative;
  bool limb;
};

const std::vector<ShapeTarget>& ShapeTargets() {
  static const std::vector<ShapeTarget> targets = {
      {"stomach-pregnant", "stomach", "-incr", "-decr", false},
      {"stomach-navel", "stomach", "-out", "-in", false},
      {"hip-scale-horiz", "hip", "-incr", "-decr", false},
      {"hip-scale-depth", "hip", "-incr", "-decr", false},
      {"hip-waist", "hip", "-up", "-down", false},
      {"breast-volume-vert", "breast", "-up", "-down", false},
      {"breast-trans", "breast", "-up", "-down", false},
      {"breast-point", "breast", "-incr", "-decr", false},
      {"breast-dist", "breast", "-incr", "-decr", false},
      {"torso-scale-depth", "torso", "-incr", "-decr", false},
      {"torso-vshape", "torso", "-incr", "-decr", false},
      {"pelvis-tone", "pelvis", "-incr", "-decr", false},
      {"upperleg-fat", "armslegs", "-incr", "-decr", true},
      {"upperarm-fat", "armslegs", "-incr", "-decr", true},
      {"lowerleg-fat", "armslegs", "-incr", "-decr", true},
  };
  return targets;
}

const ShapeTarget* FindShape(const std::string& name) {
  for (const ShapeTarget& t : ShapeTargets())
    if (name == t.name) return &t;
  return nullptr;
}

}  // namespace

const std::vector<std::string>& MakeHumanPopulationNames() {
  static const std::vector<std::string> names = {"default", "full"};
  return names;
}

const std::vector<std::string>& MakeHumanShapeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const ShapeTarget& t : ShapeTargets()) out.push_back(t.name);
    return out;
  }();
  return names;
}

const std::vector<std::string>& MakeHumanBodyShapeNames() {
  static const std::vector<std::string> names = {
      "fem-adrenal",         "fem-apple",       "fem-diamond",   "fem-full-hourglass",
      "fem-invert-triangle", "fem-lean-column", "fem-liver",     "fem-neat-hourglass",
      "fem-ovary",           "fem-rectangle",   "fem-thyroid",   "fem-triangle",
      "man-adrenal",         "man-apple",       "man-gonadal",   "man-invert-triangle",
      "man-lean-column",     "man-liver",       "man-rectangle", "man-thyroid",
      "man-trapezoid",       "man-triangle"};
  return names;
}

const std::vector<std::string>& MakeHumanHardCases() {
  static const std::vector<std::string> names = {"thighs_touch", "belly_over_waist",
                                                 "breasts_over_under_bust", "arms_on_sides"};
  return names;
}

void CheckMakeHumanShape(const std::map<std::string, double>& shape) {
  const auto& body_shapes = MakeHumanBodyShapeNames();
  for (const auto& [name, value] : shape) {
    if (name.rfind("bodyshape.", 0) == 0) {
      if (std::find(body_shapes.begin(), body_shapes.end(), name.substr(10)) == body_shapes.end())
        throw InputError("makehuman: unknown body shape '" + name + "'");
      if (!(value >= 0 && value <= 1))
        throw InputError("makehuman: shape." + name + " must be in [0, 1]");
      continue;
    }
    if (!FindShape(name)) throw InputError("makehuman: unknown shape target '" + name + "'");
    if (!(value >= -1 && value <= 1))
      throw InputError("makehuman: shape." + name + " must be in [-1, 1]");
  }
}

void AddMakeHumanShapeWeights(const std::map<std::string, double>& shape,
                              std::map<std::string, double>* weights) {
  for (const auto& [name, value] : shape) {
    if (std::abs(value) <= 1e-9) continue;
    if (name.rfind("bodyshape.", 0) == 0) {
      (*weights)["bodyshapes/bodyshapes-elvs-" + name.substr(10) + ".target"] += value;
      continue;
    }
    const ShapeTarget* t = FindShape(name);
    if (!t) throw InputError("makehuman: unknown shape target '" + name + "'");
    const std::string suffix = std::string(value > 0 ? t->positive : t->negative) + ".target";
    const std::string folder = std::string(t->folder) + "/";
    if (t->limb) {
      for (const char* side : {"l-", "r-"})
        (*weights)[folder + side + t->name + suffix] += std::abs(value);
    } else {
      (*weights)[folder + t->name + suffix] += std::abs(value);
    }
  }
}

void DrawMakeHumanEthnicWeights(const MakeHumanBodyOptions& o, MakeHumanRandom* random,
                                MakeHumanParameters* p) {
  const double a = random->Uniform(0, 1), b = random->Uniform(0, 1), c = random->Uniform(0, 1);
  p->african = o.african.value_or(a);
  p->asian = o.asian.value_or(b);
  p->caucasian = o.caucasian.value_or(c);
  const double sum = p->african + p->asian + p->caucasian;
  if (!(sum > 0)) throw InputError("makehuman: the ethnic weights are all 0");
  p->african /= sum, p->asian /= sum, p->caucasian /= sum;
}

MakeHumanParameters MakeHumanDrawFull(const MakeHumanBodyOptions& o) {
  // Its own stream: the default population's draws stay as they were.
  MakeHumanRandom random(o.seed * 0x9e3779b97f4a7c15ULL + 0x5bd1e995ULL);
  MakeHumanParameters p;
  // Every draw happens whether or not it is overridden.
  const double sex = random.Uniform(0, 1);
  const double gender = sex < 0.4   ? random.Uniform(0, 0.15)
                        : sex < 0.8 ? random.Uniform(0.85, 1)
                                    : random.Uniform(0.15, 0.85);
  p.gender = o.gender.value_or(gender);
  p.age_years = o.age_years.value_or(random.Uniform(18, 90));
  p.muscle = o.muscle.value_or(random.Uniform(0, 1));
  p.weight = o.weight.value_or(random.Uniform(0, 1));
  p.proportions = o.proportions.value_or(random.Uniform(0, 1));
  const double stature = std::clamp(random.Normal(1620 + 160 * p.gender, 100), 1450.0, 2050.0);
  p.stature_mm = o.stature_mm.value_or(stature);
  p.cup = o.cup.value_or(random.Uniform(0, 1));
  p.firmness = o.firmness.value_or(random.Uniform(0, 1));
  DrawMakeHumanEthnicWeights(o, &random, &p);
  const double spread = o.measure_spread > 0 ? 2 * o.measure_spread : 0;  // 0.6 by default
  for (const std::string& name : MakeHumanMeasureNames()) {
    const double drawn = std::clamp(random.Uniform(-spread, spread), -1.0, 1.0);
    const auto it = o.measure.find(name);
    p.measure[name] = it != o.measure.end() ? it->second : drawn;
  }
  std::map<std::string, double> shape;
  for (const std::string& name : MakeHumanShapeNames()) shape[name] = random.Uniform(-0.4, 0.4);
  // A body shape of the matching sex, to a random degree.
  const bool woman = p.gender < 0.5;
  const auto& shapes = MakeHumanBodyShapeNames();
  const std::size_t first = woman ? 0 : 12, count = woman ? 12 : 10;
  const std::size_t pick =
      first +
      std::min<std::size_t>(
          count - 1, static_cast<std::size_t>(random.Uniform(0, 1) * static_cast<double>(count)));
  shape["bodyshape." + shapes[pick]] = random.Uniform(0, 0.8);
  // One subject in five gets each hard case, pushed well into it.
  const double u = random.Uniform(0, 1), strength = random.Uniform(0, 1);
  p.hard_case = u < 0.2 ? 1 : u < 0.4 ? 2 : u < 0.6 ? 3 : u < 0.8 ? 4 : 0;
  switch (p.hard_case) {
    case 1:  // thighs that touch: fat, wide upper legs on a heavy body
      shape["upperleg-fat"] = 0.7 + 0.3 * strength;
      if (!o.measure.count("thigh-circ")) p.measure["thigh-circ"] = 0.6 + 0.4 * strength;
      if (!o.weight) p.weight = std::max(p.weight, 0.85);
      break;
    case 2:  // a belly that hangs over the waist
      shape["stomach-pregnant"] = 0.5 + 0.5 * strength;
      if (!o.weight) p.weight = std::max(p.weight, 0.55);
      break;
    case 3:  // large, soft breasts over the under-bust fold
      if (!o.gender) p.gender = std::min(p.gender, 0.1);
      if (!o.cup) p.cup = 0.8 + 0.2 * strength;
      if (!o.firmness) p.firmness = 0.25 * strength;
      shape["breast-volume-vert"] = -(0.5 + 0.5 * strength);
      break;
    case 4:  // arms resting on the sides: heavy arms and hips
      if (!o.weight) p.weight = std::max(p.weight, 0.8);
      shape["upperarm-fat"] = 0.5 + 0.5 * strength;
      shape["hip-scale-horiz"] = 0.3 + 0.5 * strength;
      break;
    default:
      break;
  }
  for (const auto& [name, value] : o.shape) shape[name] = value;
  p.shape = shape;
  return p;
}

}  // namespace bespoke
