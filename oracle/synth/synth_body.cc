#include "oracle/synth/synth_body.h"

#include <cstdlib>
#include <stdexcept>

#include "oracle/body/parametric_body.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/makehuman/makehuman_model.h"
#include "oracle/makehuman/makehuman_pose.h"
#include "oracle/synth/rule_landmarks.h"
#include "oracle/truth/defined_landmarks.h"
#include "scanners/core/errors.h"

namespace bespoke {

void SynthBodyOptions::Check() const {
  if (model != "parametric" && model != "makehuman") {
    throw InputError("body model must be parametric or makehuman, not '" + model + "'");
  }
  if (population != "default" && population != "full")
    throw InputError("population must be default or full, not '" + population + "'");
  for (const std::string& p : params) ParseNamedValue(p);
  if (!posture.empty()) ParseMakeHumanPosture(posture);
}

namespace {

// A posture on the parametric body: its arm abduction and stance; what it
// cannot build is an InputError.
void ApplyParametricPosture(const std::string& name, ParametricBodyOptions* p) {
  const MakeHumanPosture posture = ParseMakeHumanPosture(name);
  if (posture.lean_deg != 0 || posture.twist_deg != 0 || posture.head_turn_deg != 0)
    throw InputError("posture '" + name +
                     "': the parametric body has no lean, twist or head turn; use --model "
                     "makehuman");
  if (posture.arm_abduction_deg) p->arm_abduction_deg = *posture.arm_abduction_deg;
  if (posture.stance_mm) p->stance_width_mm = *posture.stance_mm;
}

}  // namespace

std::filesystem::path DefaultMakeHumanDir() {
  const char* env = std::getenv("BESPOKE_SHARED_DIR");
  const std::filesystem::path shared =
      env ? std::filesystem::path(env) : std::filesystem::path("../shared");
  return shared / "data" / "bodies" / "makehuman";
}

std::pair<std::string, double> ParseNamedValue(const std::string& kv) {
  const size_t eq = kv.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("a parameter must be name=value, not '" + kv + "'");
  const std::string text = kv.substr(eq + 1);
  try {
    size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument("trailing text");
    return {kv.substr(0, eq), value};
  } catch (const std::exception&) {
    throw InputError("parameter " + kv + ": '" + text + "' is not a number");
  }
}

SynthBodyGenerator::SynthBodyGenerator() = default;
SynthBodyGenerator::~SynthBodyGenerator() = default;

Body SynthBodyGenerator::Generate(const SynthBodyOptions& options) {
  options.Check();
  if (options.model == "parametric") {
    ParametricBodyOptions p;
    p.seed = options.seed;
    p = SeededOptions(p, options.population);
    for (const std::string& kv : options.params) {
      const auto [name, value] = ParseNamedValue(kv);
      p.Set(name, value);
    }
    if (!options.posture.empty()) ApplyParametricPosture(options.posture, &p);
    p.Check();
    ParametricBodyDetails details;
    Body body = GenerateParametricBody(p, &details);
    PlaceRuleLandmarks(RuleLandmarkOptions{}, p, details, &body);
    PlaceDefinedLandmarks(DefinedLandmarkOptions{}, {}, &body);
    return body;
  }
  const std::filesystem::path dir =
      options.makehuman_dir.empty() ? DefaultMakeHumanDir() : options.makehuman_dir;
  if (options.makehuman_dir.empty() && !std::filesystem::exists(dir)) {
    throw InputError(dir,
                     "MakeHuman data not found; give --makehuman-dir or set BESPOKE_SHARED_DIR to "
                     "the shared data folder");
  }
  if (!makehuman_ || dir != makehuman_dir_) {
    makehuman_ = std::make_unique<MakeHumanModel>(dir);
    makehuman_dir_ = dir;
  }
  MakeHumanBodyOptions mh;
  mh.seed = options.seed;
  mh.population = options.population;
  if (!options.posture.empty()) mh.posture = ParseMakeHumanPosture(options.posture);
  for (const std::string& kv : options.params) {
    const auto [name, value] = ParseNamedValue(kv);
    mh.Set(name, value);
  }
  mh.Check();
  return GenerateMakeHumanBody(mh, makehuman_.get());
}

Body GenerateSynthBody(const SynthBodyOptions& options) {
  SynthBodyGenerator generator;
  return generator.Generate(options);
}

}  // namespace bespoke
