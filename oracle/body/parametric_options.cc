// ParametricBodyOptions: ranges, names, the average man, and seeded draws.
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "oracle/body/parametric_body.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Every numeric field by name, for Set() and ToMap().
std::vector<std::pair<const char*, double ParametricBodyOptions::*>> DoubleFields() {
  using O = ParametricBodyOptions;
  return {{"stature_mm", &O::stature_mm},
          {"neck_girth_mm", &O::neck_girth_mm},
          {"chest_girth_mm", &O::chest_girth_mm},
          {"bust_girth_mm", &O::bust_girth_mm},
          {"under_bust_girth_mm", &O::under_bust_girth_mm},
          {"waist_girth_mm", &O::waist_girth_mm},
          {"middle_hip_girth_mm", &O::middle_hip_girth_mm},
          {"hip_girth_mm", &O::hip_girth_mm},
          {"upper_arm_girth_mm", &O::upper_arm_girth_mm},
          {"wrist_girth_mm", &O::wrist_girth_mm},
          {"thigh_girth_mm", &O::thigh_girth_mm},
          {"knee_girth_mm", &O::knee_girth_mm},
          {"calf_girth_mm", &O::calf_girth_mm},
          {"ankle_girth_mm", &O::ankle_girth_mm},
          {"arm_length_mm", &O::arm_length_mm},
          {"crotch_height_mm", &O::crotch_height_mm},
          {"shoulder_width_mm", &O::shoulder_width_mm},
          {"stance_width_mm", &O::stance_width_mm},
          {"arm_abduction_deg", &O::arm_abduction_deg},
          {"ring_spacing_mm", &O::ring_spacing_mm},
          {"max_girth_deficit_mm", &O::max_girth_deficit_mm}};
}

void CheckRange(const char* name, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InputError(std::string("parametric body: ") + name + " = " + std::to_string(value) +
                     " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
}

void CheckRatio(const char* name, double value, const char* of, double reference, double lo,
                double hi) {
  const double r = value / reference;
  if (!(r >= lo && r <= hi)) {
    throw InputError(std::string("parametric body: ") + name + " = " + std::to_string(value) +
                     " is " + std::to_string(r) + " x " + of + "; allowed " + std::to_string(lo) +
                     "-" + std::to_string(hi));
  }
}

}  // namespace

void ParametricBodyOptions::Check() const {
  CheckRange("stature_mm", stature_mm, 1300, 2200);
  CheckRange("neck_girth_mm", neck_girth_mm, 250, 600);
  CheckRange("chest_girth_mm", chest_girth_mm, 600, 1600);
  CheckRange("bust_girth_mm", bust_girth_mm, 600, 1700);
  CheckRange("under_bust_girth_mm", under_bust_girth_mm, 550, 1500);
  CheckRange("waist_girth_mm", waist_girth_mm, 450, 1600);
  CheckRange("middle_hip_girth_mm", middle_hip_girth_mm, 550, 1700);
  CheckRange("hip_girth_mm", hip_girth_mm, 650, 1800);
  CheckRange("upper_arm_girth_mm", upper_arm_girth_mm, 180, 550);
  CheckRange("wrist_girth_mm", wrist_girth_mm, 110, 260);
  CheckRange("thigh_girth_mm", thigh_girth_mm, 350, 950);
  CheckRange("knee_girth_mm", knee_girth_mm, 250, 650);
  CheckRange("calf_girth_mm", calf_girth_mm, 230, 650);
  CheckRange("ankle_girth_mm", ankle_girth_mm, 160, 400);
  CheckRatio("arm_length_mm", arm_length_mm, "stature", stature_mm, 0.28, 0.40);
  CheckRatio("crotch_height_mm", crotch_height_mm, "stature", stature_mm, 0.40, 0.50);
  CheckRatio("shoulder_width_mm", shoulder_width_mm, "stature", stature_mm, 0.18, 0.30);
  CheckRatio("stance_width_mm", stance_width_mm, "stature", stature_mm, 0.08, 0.25);
  CheckRange("arm_abduction_deg", arm_abduction_deg, 15, 90);
  // Girths that must keep their order for the torso to be a plausible shape.
  CheckRatio("bust_girth_mm", bust_girth_mm, "under_bust_girth_mm", under_bust_girth_mm, 1.0, 1.45);
  CheckRatio("chest_girth_mm", chest_girth_mm, "under_bust_girth_mm", under_bust_girth_mm, 0.95,
             1.35);
  CheckRatio("waist_girth_mm", waist_girth_mm, "hip_girth_mm", hip_girth_mm, 0.55, 1.25);
  CheckRatio("middle_hip_girth_mm", middle_hip_girth_mm, "hip_girth_mm", hip_girth_mm, 0.7, 1.15);
  CheckRatio("thigh_girth_mm", thigh_girth_mm, "hip_girth_mm", hip_girth_mm, 0.42, 0.72);
  CheckRatio("knee_girth_mm", knee_girth_mm, "thigh_girth_mm", thigh_girth_mm, 0.5, 0.9);
  CheckRatio("calf_girth_mm", calf_girth_mm, "knee_girth_mm", knee_girth_mm, 0.8, 1.3);
  CheckRatio("ankle_girth_mm", ankle_girth_mm, "calf_girth_mm", calf_girth_mm, 0.5, 0.85);
  CheckRatio("wrist_girth_mm", wrist_girth_mm, "upper_arm_girth_mm", upper_arm_girth_mm, 0.4, 0.75);
  CheckRatio("shoulder_width_mm", shoulder_width_mm, "chest girth / pi", chest_girth_mm / 3.14159,
             1.0, 1.6);
  if (torso_segments < 48 || torso_segments > 2048 || torso_segments % 8 != 0)
    throw InputError("parametric body: torso_segments must be a multiple of 8 in [48, 2048]");
  if (arm_segments < 32 || arm_segments > 1024 || arm_segments % 4 != 0)
    throw InputError("parametric body: arm_segments must be a multiple of 4 in [32, 1024]");
  if (girth_ring_segments < 16 || girth_ring_segments > 8192)
    throw InputError("parametric body: girth_ring_segments must be in [16, 8192]");
  CheckRange("ring_spacing_mm", ring_spacing_mm, 2, 40);
  CheckRange("max_girth_deficit_mm", max_girth_deficit_mm, 1e-6, 100);
}

void ParametricBodyOptions::Set(const std::string& name, double value) {
  if (name == "seed") {
    if (!(value >= 0) || value != std::floor(value))
      throw InputError("parametric body: seed must be a whole number >= 0");
    seed = static_cast<std::uint64_t>(value);
    return;
  }
  if (name == "torso_segments" || name == "arm_segments" || name == "girth_ring_segments") {
    if (value != std::floor(value) || !(std::abs(value) < 1e6)) {
      throw InputError("parametric body: " + name + " must be a whole number");
    }
    (name == "torso_segments" ? torso_segments
     : name == "arm_segments" ? arm_segments
                              : girth_ring_segments) = static_cast<int>(value);
    return;
  }
  for (const auto& [field, member] : DoubleFields()) {
    if (name == field) {
      this->*member = value;
      return;
    }
  }
  std::string known = "seed, torso_segments, arm_segments, girth_ring_segments";
  for (const auto& field : DoubleFields()) known += std::string(", ") + field.first;
  throw InputError("parametric body: unknown parameter '" + name + "' (known: " + known + ")");
}

std::map<std::string, double> ParametricBodyOptions::ToMap() const {
  std::map<std::string, double> out;
  for (const auto& [field, member] : DoubleFields()) out[field] = this->*member;
  out["seed"] = static_cast<double>(seed);
  out["drawn_from_seed"] = static_cast<double>(drawn_from_seed);
  out["torso_segments"] = torso_segments;
  out["arm_segments"] = arm_segments;
  out["girth_ring_segments"] = girth_ring_segments;
  return out;
}

ParametricBodyOptions ParametricBodyOptions::AverageMan() {
  ParametricBodyOptions o;
  o.stature_mm = 1760;
  o.neck_girth_mm = 390;
  o.chest_girth_mm = 1000;
  o.bust_girth_mm = 1000;
  o.under_bust_girth_mm = 920;
  o.waist_girth_mm = 880;
  o.middle_hip_girth_mm = 940;
  o.hip_girth_mm = 990;
  o.upper_arm_girth_mm = 310;
  o.wrist_girth_mm = 175;
  o.thigh_girth_mm = 560;
  o.knee_girth_mm = 385;
  o.calf_girth_mm = 375;
  o.ankle_girth_mm = 235;
  o.arm_length_mm = 600;
  o.crotch_height_mm = 815;
  o.shoulder_width_mm = 410;
  o.stance_width_mm = 230;
  return o;
}

namespace {

// Keeps the pose and resolution of `from` in `to`.
void KeepPoseAndResolution(const ParametricBodyOptions& from, ParametricBodyOptions* to) {
  to->arm_abduction_deg = from.arm_abduction_deg;
  to->torso_segments = from.torso_segments;
  to->arm_segments = from.arm_segments;
  to->ring_spacing_mm = from.ring_spacing_mm;
  to->girth_ring_segments = from.girth_ring_segments;
  to->max_girth_deficit_mm = from.max_girth_deficit_mm;
}

// How far each girth of a drawn body strays from the build (relative SDs of
// the jitter factors; bust_ratio is a woman's bust over her under-bust).
struct GirthSpread {
  double belly, hips, neck, under_bust, chest, bust_ratio, bust, middle_hip;
  double upper_arm, wrist, thigh, knee, calf, ankle;
  bool middle_hip_at_least_waist;  // a belly over the hips keeps the middle hip >= the waist
};
constexpr GirthSpread kDefaultSpread{0.06, 0.04, 0.03, 0.03, 0.02, 1.19, 0.04, 0.02,
                                     0.04, 0.03, 0.03, 0.03, 0.04, 0.03, false};
constexpr GirthSpread kFullSpread{0.12, 0.08, 0.05, 0.05, 0.03, 1.2,  0.08, 0.02,
                                  0.08, 0.05, 0.05, 0.05, 0.06, 0.05, true};

// A woman's chest girth, at the armpits above the breasts, lies between her
// under-bust and bust girths; as its share of the way up, the draw keeps
// shares up to kChestShareKnee and brings larger ones (a chest up to or past
// the bust, which leaves no breast below it) smoothly under
// kChestShareCeiling (MakeHuman's women: 0.37-0.98 where the chest exceeds
// the under-bust).
constexpr double kChestShareKnee = 0.85, kChestShareCeiling = 0.95;

double ChestShare(double drawn) {
  if (drawn <= kChestShareKnee) return drawn;
  const double room = kChestShareCeiling - kChestShareKnee;
  return kChestShareKnee + room * (1 - std::exp(-(drawn - kChestShareKnee) / room));
}

// Scales the girths of `o` (a sex's average body) by the build: trunk girths
// share it, the belly and hips vary on their own too. `jitter(sd)` draws a
// factor 1 + sd * (clipped normal); the draw order is part of the seed's body.
void DrawGirths(const GirthSpread& sd, bool man, double build, double girth_scale,
                const std::function<double(double)>& jitter, ParametricBodyOptions* o) {
  const double belly = jitter(sd.belly), hips = jitter(sd.hips);
  o->neck_girth_mm *= girth_scale * jitter(sd.neck);
  o->under_bust_girth_mm *= girth_scale * jitter(sd.under_bust);
  o->chest_girth_mm = o->under_bust_girth_mm * (man ? 1.087 : 1.154) * jitter(sd.chest);
  o->bust_girth_mm =
      man ? o->chest_girth_mm : o->under_bust_girth_mm * (sd.bust_ratio * jitter(sd.bust));
  const double rise_mm = o->bust_girth_mm - o->under_bust_girth_mm;
  if (!man && rise_mm > 0) {
    const double share = (o->chest_girth_mm - o->under_bust_girth_mm) / rise_mm;
    o->chest_girth_mm = o->under_bust_girth_mm + ChestShare(share) * rise_mm;
  }
  o->waist_girth_mm *= girth_scale * belly * (build > 1 ? build : 1.0);
  o->hip_girth_mm *= girth_scale * hips;
  const double middle = 0.5 * (o->waist_girth_mm + o->hip_girth_mm);
  o->middle_hip_girth_mm =
      (sd.middle_hip_at_least_waist ? std::max(middle, o->waist_girth_mm) : middle) *
      jitter(sd.middle_hip);
  o->upper_arm_girth_mm *= girth_scale * jitter(sd.upper_arm);
  o->wrist_girth_mm *= std::sqrt(girth_scale) * jitter(sd.wrist);
  o->thigh_girth_mm *= girth_scale * hips * jitter(sd.thigh);
  o->knee_girth_mm *= std::sqrt(girth_scale) * jitter(sd.knee);
  o->calf_girth_mm *= std::sqrt(girth_scale) * jitter(sd.calf);
  o->ankle_girth_mm *= std::sqrt(girth_scale) * jitter(sd.ankle);
}

// The "full" population: any stature of 1450-2050 mm, builds from very thin
// to obese, and belly, hips and bust drawn apart from the build.
ParametricBodyOptions FullRangeOptions(const ParametricBodyOptions& options) {
  std::mt19937_64 rng(options.seed * 0xD1B54A32D192ED03ULL + 0x2545F491ULL);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0, 1);
  const auto clipped = [&](double lo, double hi) { return std::clamp(normal(rng), lo, hi); };
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const bool man = uniform(rng) < 0.5;
    ParametricBodyOptions o = man ? ParametricBodyOptions::AverageMan() : ParametricBodyOptions();
    KeepPoseAndResolution(options, &o);
    const double stature = std::clamp(o.stature_mm + 100 * normal(rng), 1450.0, 2050.0);
    const double length_scale = stature / o.stature_mm;
    const double build = std::clamp(1 + 0.18 * clipped(-2, 2.8), 0.65, 1.5);
    const double girth_scale = build * std::sqrt(length_scale);
    const auto jitter = [&](double sd) { return 1 + sd * clipped(-2.5, 2.5); };
    o.stature_mm = stature;
    o.arm_length_mm *= length_scale * jitter(0.03);
    o.crotch_height_mm *= length_scale * jitter(0.03);
    o.shoulder_width_mm *= std::sqrt(girth_scale) * length_scale * jitter(0.05);
    o.stance_width_mm *= length_scale;
    DrawGirths(kFullSpread, man, build, girth_scale, jitter, &o);
    o.seed = 0;
    o.drawn_from_seed = options.seed;
    try {
      o.Check();
    } catch (const InputError&) {
      continue;
    }
    return o;
  }
  throw InternalError("parametric body: no valid full-range draw for seed " +
                      std::to_string(options.seed));
}

}  // namespace

ParametricBodyOptions SeededOptions(const ParametricBodyOptions& options,
                                    const std::string& population) {
  if (population != "default" && population != "full")
    throw InputError("parametric body: unknown population '" + population + "' (default, full)");
  if (options.seed == 0) return options;
  if (population == "full") return FullRangeOptions(options);
  std::mt19937_64 rng(options.seed * 0x9E3779B97F4A7C15ULL + 0x1234567ULL);
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto clipped = [&]() { return std::clamp(normal(rng), -2.2, 2.2); };
  // Rejection loop: a draw that breaks a range or ratio is redrawn (rare).
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const bool man = std::uniform_real_distribution<double>(0, 1)(rng) < 0.5;
    ParametricBodyOptions o = man ? ParametricBodyOptions::AverageMan() : ParametricBodyOptions();
    KeepPoseAndResolution(options, &o);
    const double stature_scale = 1 + 0.038 * clipped();  // SD about 65 mm
    const double build = 1 + 0.10 * clipped();           // light to heavy
    const double length_scale = stature_scale;
    const double girth_scale = build * std::sqrt(stature_scale);
    const auto jitter = [&](double sd) { return 1 + sd * clipped(); };
    o.stature_mm *= stature_scale;
    o.arm_length_mm *= length_scale * jitter(0.02);
    o.crotch_height_mm *= length_scale * jitter(0.02);
    o.shoulder_width_mm *= std::sqrt(girth_scale) * length_scale * jitter(0.03);
    o.stance_width_mm *= length_scale;
    DrawGirths(kDefaultSpread, man, build, girth_scale, jitter, &o);
    o.seed = 0;
    o.drawn_from_seed = options.seed;
    try {
      o.Check();
    } catch (const InputError&) {
      continue;
    }
    return o;
  }
  throw InternalError("parametric body: no valid draw for seed " + std::to_string(options.seed));
}

}  // namespace bespoke
