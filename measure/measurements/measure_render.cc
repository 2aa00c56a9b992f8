#include "measure/measurements/measure_render.h"

namespace bespoke {
namespace {

Rgb ColourOf(const Measurement& m) {
  if (!m.flags.empty()) return {235, 130, 20};
  switch (m.method) {
    case MeasurementMethod::kSectionHull:
      return {210, 30, 30};
    case MeasurementMethod::kGeodesic:
      return {20, 90, 220};
    case MeasurementMethod::kBreadth:
    case MeasurementMethod::kPointToLine:
      return {30, 150, 60};
    case MeasurementMethod::kHeight:
      break;
  }
  return {120, 120, 120};
}

}  // namespace

RgbImage RenderMeasurements(const PointCloud& body_cloud, const LandmarkSet& landmarks,
                            const MeasureResult& result, int height_px) {
  RenderScene scene;
  scene.cloud = &body_cloud;
  for (const auto& [name, l] : landmarks.points) {
    LabelledPoint p{name, l.position_mm};
    if (l.confidence < 0.5) p.color = {235, 130, 20};
    scene.points.push_back(p);
  }
  for (const Measurement& m : result.measurements) {
    if (m.kind == MeasurementKind::kHeight || m.geometry.rows() < 2) continue;
    Polyline line;
    line.points = m.geometry;
    line.color = ColourOf(m);
    line.closed = m.kind == MeasurementKind::kGirth;
    scene.polylines.push_back(std::move(line));
  }
  RenderOptions options;
  options.views = {View::kFront, View::kRight};
  options.height_px = height_px;
  options.label_font_px = 11;
  options.title = "girths red, paths blue, breadths green, flagged orange";
  return Render(options, scene);
}

void WriteMeasureRender(const std::filesystem::path& file, const PointCloud& body_cloud,
                        const LandmarkSet& landmarks, const MeasureResult& result, int height_px) {
  WritePng(RenderMeasurements(body_cloud, landmarks, result, height_px), file);
}

}  // namespace bespoke
