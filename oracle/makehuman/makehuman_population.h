// Named populations of MakeHuman bodies and the shape targets beyond the
// macro parameters (belly, hips, breasts, limbs' fat, body shapes).
//
// Populations (MakeHumanBodyOptions::population):
//   "default": the draw of MakeHumanDraw (makehuman_body.h), unchanged, so
//     earlier seeds give the same bodies.
//   "full": the whole range a shop sees: gender 0-1 continuous (40 % women,
//     40 % men, 20 % in between), age 18-90, muscle and weight 0-1,
//     proportions 0-1, stature 1450-2050 mm, cup and firmness 0-1, every
//     measure/ target in +-0.6, the shape targets below drawn around 0, a
//     body shape of the matching sex, and on purpose, for one subject in
//     five each, one hard case (kHardCases): thighs that touch, a belly over
//     the waist, breasts over the under-bust, arms resting on the sides.
// The draw uses its own stream of the seed; values set in the options
// override the draw, as for the default population.
//
// Shape targets: a value in [-1, 1] by name (MakeHumanShapeNames()); a
// positive value weights the "-incr" (or "-up") file, a negative one the
// "-decr" (or "-down") file, by |value|; limb names apply both sides'
// files. Body shapes ("bodyshape.<name>", e.g. "bodyshape.fem-apple") take
// 0..1 and weight bodyshapes/bodyshapes-elvs-<name>.target.
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_POPULATION_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_POPULATION_H_

#include <map>
#include <string>
#include <vector>

namespace bespoke {

class MakeHumanRandom;
struct MakeHumanBodyOptions;
struct MakeHumanParameters;

// The populations' names: "default", "full".
const std::vector<std::string>& MakeHumanPopulationNames();

// The shape targets' names (without "bodyshape."), e.g. "stomach-pregnant",
// "hip-scale-horiz", "breast-volume-vert", "upperleg-fat".
const std::vector<std::string>& MakeHumanShapeNames();

// The body shapes' names ("fem-apple", ..., "man-trapezoid").
const std::vector<std::string>& MakeHumanBodyShapeNames();

// The hard cases drawn on purpose by the "full" population, in order of
// their code 1..4 (0 is none): "thighs_touch", "belly_over_waist",
// "breasts_over_under_bust", "arms_on_sides".
const std::vector<std::string>& MakeHumanHardCases();

// InputError naming the shape value when its name is unknown or its value
// out of range.
void CheckMakeHumanShape(const std::map<std::string, double>& shape);

// Target weights of the shape values (file name relative to targets/ ->
// weight), added to `weights`.
void AddMakeHumanShapeWeights(const std::map<std::string, double>& shape,
                              std::map<std::string, double>* weights);

// Draws the three ethnic weights (three uniform draws, always made), takes
// the options' overrides and normalizes them to sum 1; InputError when they
// are all 0. Shared by both populations' draws.
void DrawMakeHumanEthnicWeights(const MakeHumanBodyOptions& options, MakeHumanRandom* random,
                                MakeHumanParameters* parameters);

// The "full" population's draw for options.seed, then the options'
// overrides (as MakeHumanDraw). Sets parameters.hard_case.
MakeHumanParameters MakeHumanDrawFull(const MakeHumanBodyOptions& options);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_POPULATION_H_
