// DetectLandmarks: checks, slices the cloud and runs the detector's stages
// (landmark_context.h), then the plausibility checks (landmark_checks.h)
// and the `only` filter.
#include "measure/landmarks/landmarks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "measure/catalogue/catalogue.h"
#include "measure/landmarks/landmark_checks.h"
#include "measure/landmarks/landmark_context.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace landmarks {

std::string Side(int sign) { return sign > 0 ? "_right" : "_left"; }

void Context::Put(const std::string& name, const Eigen::Vector3d& position, double confidence,
                  const std::string& method, std::vector<std::string> flags) {
  double d2 = 0;
  index->Nearest(position, &d2);
  if (d2 > 12.0 * 12.0 && std::find(flags.begin(), flags.end(), "in_hole") == flags.end()) {
    flags.push_back("in_hole");
    confidence = std::min(confidence, 0.6);
  }
  Landmark landmark;
  landmark.position_mm = position;
  landmark.confidence = std::clamp(confidence, 0.0, 1.0);
  landmark.flags = std::move(flags);
  landmark.method = method;
  found.points[name] = landmark;
  found.missing.erase(name);
}

void Context::Missing(const std::string& name, const std::string& why) {
  if (!found.Has(name)) found.missing[name] = why;
}

int Context::SmoothExtreme(const std::vector<int>& candidates, const Eigen::Vector3d& direction,
                           double radius_mm, double band_mm) const {
  if (candidates.empty()) return -1;
  double top = -std::numeric_limits<double>::infinity();
  for (int r : candidates) top = std::max(top, P(r).dot(direction));
  int best = -1;
  double best_score = -std::numeric_limits<double>::infinity();
  std::vector<int> near;
  std::vector<double> d2;
  for (int r : candidates) {
    if (P(r).dot(direction) < top - band_mm) continue;
    index->Knn(P(r), 32, &near, &d2);
    double sum = 0;
    int n = 0;
    for (size_t k = 0; k < near.size(); ++k) {
      if (d2[k] > radius_mm * radius_mm) break;
      sum += P(near[k]).dot(direction), ++n;
    }
    const double score = sum / std::max(n, 1);
    if (score > best_score) best_score = score, best = r;
  }
  return best;
}

int Context::CapCentre(const std::vector<int>& candidates, const Eigen::Vector3d& direction,
                       double depth_mm) const {
  if (candidates.empty()) return -1;
  std::vector<double> value;
  value.reserve(candidates.size());
  for (int r : candidates) value.push_back(P(r).dot(direction));
  const size_t k = std::min<size_t>(4, value.size() - 1);
  std::nth_element(value.begin(), value.begin() + static_cast<std::ptrdiff_t>(k), value.end(),
                   std::greater<double>());
  const double top = value[k];
  std::vector<int> cap;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int r : candidates) {
    if (P(r).dot(direction) < top - depth_mm) continue;
    cap.push_back(r);
    centre += P(r);
  }
  centre /= static_cast<double>(cap.size());
  int best = cap.front();
  for (int r : cap)
    if ((P(r) - centre).squaredNorm() < (P(best) - centre).squaredNorm()) best = r;
  return best;
}

std::vector<int> Context::TrunkPieces(const Slice& s, double core_mm) const {
  std::vector<int> out;
  for (size_t i = 0; i < s.pieces.size(); ++i) {
    const Piece& p = s.pieces[i];
    if (p.lo.x() < core_mm && p.hi.x() > -core_mm) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<int> Context::TrunkRows(const Slice& s, double core_mm) const {
  std::vector<int> rows;
  if (structure.ok) {
    for (int r : s.rows)
      if (structure.part[static_cast<size_t>(r)] == Part::kTrunk) rows.push_back(r);
    return rows;
  }
  for (int i : TrunkPieces(s, core_mm)) {
    const auto& r = s.pieces[static_cast<size_t>(i)].rows;
    rows.insert(rows.end(), r.begin(), r.end());
  }
  return rows;
}

namespace {

// Runs a stage; an InputError inside it marks the stage's still-unplaced
// landmarks missing with its message rather than failing the whole set.
template <typename Stage>
void Run(Context* c, Stage stage, const std::vector<std::string>& names) {
  try {
    stage(c);
  } catch (const InputError& e) {
    for (const std::string& name : names) c->Missing(name, e.what());
  }
}

std::vector<std::string> Both(std::initializer_list<const char*> names) {
  std::vector<std::string> out;
  for (const char* n : names) {
    out.push_back(std::string(n) + "_right");
    out.push_back(std::string(n) + "_left");
  }
  return out;
}

}  // namespace
}  // namespace landmarks

std::vector<ScanPart> FindBodyParts(const PointCloud& cloud) {
  if (cloud.size() == 0 || !cloud.points.allFinite()) return {};
  landmarks::BodyStructure structure =
      landmarks::FindBodyStructure(landmarks::BodyStructureOptions{}, cloud.points, cloud.normals,
                                   cloud.points.col(2).maxCoeff());
  if (!structure.ok) return {};
  return std::move(structure.part);
}

LandmarkSet DetectLandmarks(const LandmarkOptions& options, const PointCloud& cloud,
                            Progress* progress) {
  using namespace landmarks;
  options.Check();
  if (cloud.size() < 2000) {
    throw InputError("landmarks: the cloud has " + std::to_string(cloud.size()) +
                     " points; a cleaned body scan has tens of thousands");
  }
  if (!cloud.points.allFinite()) throw InputError("landmarks: the cloud has non-finite points");
  const double height = cloud.points.col(2).maxCoeff() - cloud.points.col(2).minCoeff();
  if (height < 900 || height > 2600) {
    throw InputError("landmarks: the cloud is " + std::to_string(static_cast<int>(height)) +
                     " mm tall; expected a standing adult in the body frame (mm, +z up)");
  }
  Context c(cloud.points, cloud.normals);
  c.index = std::make_unique<PointIndex>(cloud.points);
  SliceOptions slice_options;
  slice_options.step_mm = options.slice_step_mm;
  slice_options.half_thickness_mm = options.slice_half_thickness_mm;
  c.step = options.slice_step_mm;
  c.slices = SliceCloud(slice_options, cloud.points);
  c.structure = FindBodyStructure(BodyStructureOptions{}, cloud.points, cloud.normals,
                                  cloud.points.col(2).maxCoeff());
  if (progress) progress->Begin("landmarks", 3);
  FindCrownAndCrotch(&c);  // InputError here: not a standing person
  Run(&c, FindArmpits, Both({"armpit", "axilla_front", "axilla_back"}));
  Run(&c, FindTrunkLevels,
      {"bust_right", "bust_left", "under_bust", "front_waist", "back_waist", "side_waist_right",
       "side_waist_left", "middle_hip_front", "hip_back", "hip_right", "hip_left"});
  ProgressUpdate(progress, 1);
  Run(&c, FindNeckAndShoulders,
      {"back_neck", "front_neck", "side_neck_right", "side_neck_left", "shoulder_right",
       "shoulder_left", "axilla_front_right", "axilla_front_left", "axilla_back_right",
       "axilla_back_left"});
  Run(&c, FindArms, Both({"upper_arm", "elbow", "wrist"}));
  Run(&c, FindLegs, Both({"thigh", "knee", "calf", "ankle_inside", "ankle_outside"}));
  ProgressUpdate(progress, 2);
  CheckLandmarks(&c.found, c.crown_z);

  LandmarkSet set = std::move(c.found);
  if (c.structure.ok) {
    // The found armpits give the raised arm's fillet back to the trunk
    // (body_structure.h); a doubtful armpit changes nothing.
    for (int side : {0, 1}) {
      const std::string name = side == 0 ? "armpit_right" : "armpit_left";
      if (!set.Has(name) || set.points.at(name).confidence < 0.5) continue;
      const Eigen::Vector3d p = set.points.at(name).position_mm;
      ReturnFilletToTrunk(cloud.points, side, p, c.index->Nearest(p), &c.structure);
    }
    set.parts = c.structure.part;
  }
  const Catalogue& catalogue = Catalogue::Builtin();
  for (const LandmarkDef& def : catalogue.landmarks()) {
    if (!set.Has(def.name) && !set.missing.count(def.name)) set.missing[def.name] = "not detected";
  }
  if (!options.only.empty()) {
    LandmarkSet some;
    some.parts = std::move(set.parts);
    for (const std::string& name : options.only) {
      if (set.Has(name))
        some.points[name] = set.points.at(name);
      else
        some.missing[name] = set.missing.count(name) ? set.missing.at(name) : "not detected";
    }
    set = std::move(some);
  }
  if (progress) {
    progress->Update(3);
    progress->End();
  }
  return set;
}

}  // namespace bespoke
