#include "scanners/clean/clean_json.h"

#include "scanners/core/json_io.h"

namespace bespoke {

nlohmann::json ToJson(const CleanOptions& o) {
  using nlohmann::json;
  return json{
      {"voxel_grid", {{"enabled", o.use_voxel_grid}, {"leaf_mm", o.voxel_grid.leaf_mm}}},
      {"statistical_outliers",
       {{"enabled", o.use_statistical_outliers},
        {"mean_k", o.statistical_outliers.mean_k},
        {"stddev_mul", o.statistical_outliers.stddev_mul}}},
      {"radius_outliers",
       {{"enabled", o.use_radius_outliers},
        {"radius_mm", o.radius_outliers.radius_mm},
        {"min_neighbors", o.radius_outliers.min_neighbors}}},
      {"floor",
       {{"enabled", o.use_floor},
        {"distance_mm", o.floor.distance_mm},
        {"max_planes", o.floor.max_planes},
        {"min_inlier_fraction", o.floor.min_inlier_fraction},
        {"max_axis_angle_deg", o.floor.max_axis_angle_deg},
        {"min_one_side_fraction", o.floor.min_one_side_fraction},
        {"min_body_height_mm", o.floor.min_body_height_mm},
        {"body_gap_mm", o.floor.body_gap_mm},
        {"ransac_sample", o.floor.ransac_sample},
        {"ransac_iterations", o.floor.ransac_iterations},
        {"seed", o.floor.seed}}},
      {"largest_cluster",
       {{"enabled", o.use_largest_cluster}, {"tolerance_mm", o.cluster.tolerance_mm}}},
      {"normals",
       {{"enabled", o.use_normals},
        {"k", o.normals.k},
        {"grid_cell_mm", o.normals.grid_cell_mm},
        {"hole_close_mm", o.normals.hole_close_mm},
        {"probe_mm", o.normals.probe_mm}}},
      {"body_frame",
       {{"end_fraction", o.body_frame.end_fraction},
        {"min_end_area_ratio", o.body_frame.min_end_area_ratio},
        {"foot_fraction", o.body_frame.foot_fraction},
        {"ankle_low_fraction", o.body_frame.ankle_low_fraction},
        {"ankle_high_fraction", o.body_frame.ankle_high_fraction},
        {"min_foot_offset_mm", o.body_frame.min_foot_offset_mm},
        {"min_nose_cue_mm", o.body_frame.min_nose_cue_mm}}},
      {"threads", o.threads},
  };
}

nlohmann::json ToJson(const CleanResult& r) {
  using nlohmann::json;
  json stages = json::array();
  for (const CleanStage& s : r.stages) {
    stages.push_back({{"name", s.name},
                      {"enabled", s.enabled},
                      {"points_in", s.points_in},
                      {"points_out", s.points_out},
                      {"time_s", s.time_s},
                      {"cpu_s", s.cpu_s}});
  }
  json floor = nullptr;
  if (r.floor) {
    floor = {{"up_scanner", ToJson(r.floor->up)}, {"offset_mm", r.floor->offset_mm}};
  }
  const BodyFrame& f = r.frame;
  return json{
      {"stages", stages},
      {"points_out", r.cloud.size()},
      {"total_time_s", r.total_time_s},
      {"non_finite_dropped", r.non_finite_dropped},
      {"body_from_scanner", ToJson(Eigen::Affine3d(r.body_from_scanner.matrix()))},
      {"floor", floor},
      {"floor_note", r.floor_note},
      {"clusters", r.cluster_sizes},
      {"body_frame",
       {{"up_source", f.up_source},
        {"end_area_ratio", f.end_area_ratio},
        {"lateral_ratio", f.lateral_ratio},
        {"front_source", f.front_source},
        {"foot_offset_mm", f.foot_offset_mm},
        {"feet_found", f.feet_found},
        {"nose_cue_mm", f.nose_cue_mm},
        {"height_mm", f.height_mm}}},
      {"normals",
       {{"by_exterior", r.normals.by_exterior},
        {"by_propagation", r.normals.by_propagation},
        {"by_fallback", r.normals.by_fallback},
        {"degenerate", r.normals.degenerate},
        {"closing_mm", r.normals.closing_mm}}},
      {"flags", r.flags},
  };
}

}  // namespace bespoke
