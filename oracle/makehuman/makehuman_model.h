// The MakeHuman base mesh and its morph targets (CC0 assets in
// ../shared/data/bodies/makehuman; MakeHuman's AGPL code is not used).
//
// Load: reads base.obj with ReadMesh (scanners/io), keeps only the faces of
// the skin group `body` (its quads arrive fan-split into two triangles
// each), drops the vertices no body face uses, and keeps the map from body
// vertices back to base.obj vertex indices so targets and landmarks apply.
// Checks the body is a closed 2-manifold (every edge in exactly two faces);
// InputError naming base.obj otherwise.
//
// Morph: base body + sum of weight * target, in MakeHuman's units and axes
// (decimetres, y up, the person faces +z, their left is +x). Targets are read
// from <dir>/targets/<name> on first use and cached (a class: the base mesh
// and the cache are reused across bodies). Not thread-safe.
//
// BodyFromMakeHuman(): the rotation and scale into the body frame
// (docs/contracts.md): x_body = -100 x_mh, y_body = 100 z_mh,
// z_body = 100 y_mh (mm; a proper rotation: facing +z -> +y, up y -> +z,
// the person's right (-x_mh) -> +x). The translation to put the feet on
// z = 0 and the origin between them is the caller's (GenerateMakeHumanBody).
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_MODEL_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_MODEL_H_

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "oracle/makehuman/makehuman_target.h"
#include "scanners/core/types.h"

namespace bespoke {

struct MakeHumanRig;

class MakeHumanModel {
 public:
  // `dir` holds base.obj and targets/. Throws InputError for a missing or
  // malformed base.obj, a missing `body` group, an open or non-manifold body.
  explicit MakeHumanModel(const std::filesystem::path& dir);
  ~MakeHumanModel();

  const std::filesystem::path& dir() const { return dir_; }
  // The skin only: #V x 3 decimetres (MakeHuman axes), #F x 3 triangles.
  const TriangleMesh& base_body() const { return body_; }
  // Body vertex -> base.obj vertex (#V entries, increasing).
  const std::vector<int>& base_index() const { return base_index_; }
  // Body vertex of a base.obj vertex, or -1 when it is not part of the skin.
  int BodyVertex(int base_vertex) const;
  int num_base_vertices() const { return num_base_vertices_; }

  // The target at `name` (relative to targets/, e.g.
  // "macrodetails/height/female-young-averagemuscle-averageweight-maxheight.target").
  // InputError when missing/malformed or when it indexes past base.obj's vertices.
  const MakeHumanTarget& Target(const std::string& name);
  bool HasTarget(const std::string& name) const;

  // base_body() + sum of weight * target (MakeHuman units and axes).
  TriangleMesh Morph(const std::map<std::string, double>& weights);

  // The same morph, plus the centres of base.obj's joint helper groups
  // ("joint-r-elbow", "joint-neck", ...: small meshes around each joint of
  // MakeHuman's skeleton, morphed with the body), MakeHuman units and axes.
  struct Morphed {
    TriangleMesh body;
    std::map<std::string, Eigen::Vector3d> joints;
  };
  Morphed MorphWithJoints(const std::map<std::string, double>& weights);
  const std::map<std::string, std::vector<int>>& joint_vertices() const { return joints_; }
  // Every base.obj vertex morphed (#base vertices x 3, MakeHuman units and
  // axes): the skeleton's joints are means of such vertices, helper
  // geometry included.
  Eigen::MatrixX3d MorphAll(const std::map<std::string, double>& weights);
  // The skin's rows of MorphAll's result (#V x 3).
  Eigen::MatrixX3d SkinRows(const Eigen::MatrixX3d& all) const;

  static Eigen::Affine3d BodyFromMakeHuman();

  // The default skeleton and skin weights from <dir>/rig (makehuman_pose.h),
  // read on first use. InputError when missing or malformed.
  const MakeHumanRig& Rig();

 private:
  std::filesystem::path dir_;
  TriangleMesh body_;
  std::vector<int> base_index_;
  std::vector<int> body_vertex_;  // base.obj vertex -> body vertex or -1
  int num_base_vertices_ = 0;
  Eigen::MatrixX3d base_vertices_;                  // all of base.obj's vertices
  std::map<std::string, std::vector<int>> joints_;  // joint group -> base.obj vertices
  std::map<std::string, MakeHumanTarget> cache_;
  std::unique_ptr<MakeHumanRig> rig_;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_MODEL_H_
