// Orthographic pictures of meshes and point clouds with overlays: datum
// points, girth loops, geodesic paths. For reports, docs and debugging.
//
// Input geometry is in the body frame (mm, +z up, facing +y; transform a scan
// with body_from_scanner first). Each view looks at the body horizontally
// from one side (or from above); all views of one picture share one scale
// and stand side by side. Meshes are shaded (Lambert, z-buffered); clouds
// are splatted discs shaded by their normals (by depth without normals).
// Overlay points are drawn as discs with labels (hollow when hidden behind
// the surface), polylines on top.
//
//   RenderScene scene;
//   scene.mesh = &body.mesh;
//   scene.points.push_back({"crown", crown_position});
//   WritePng(Render(RenderOptions(), scene), "body.png");
//
// OpenCV does the drawing inside render.cc; this header has no OpenCV type.
// Failure: InputError when the scene is empty or has non-finite geometry,
// when the output folder does not exist or the file is not .png.
#ifndef BESPOKE_SCANNERS_RENDER_RENDER_H_
#define BESPOKE_SCANNERS_RENDER_RENDER_H_

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

using Rgb = std::array<std::uint8_t, 3>;

// Where the viewer stands: in front of the person (+y), behind (-y), on the
// person's right (+x), left (-x), or above (+z, front up).
enum class View { kFront, kBack, kRight, kLeft, kTop };

struct LabelledPoint {
  std::string label;         // drawn beside the point; empty = no label
  Eigen::Vector3d position;  // body frame, mm
  Rgb color = {220, 30, 30};
};

struct Polyline {
  Eigen::MatrixX3d points;  // #K x 3, body frame, mm
  Rgb color = {20, 90, 220};
  bool closed = false;  // join the last point to the first (girth loops)
  double width_px = 2;
};

struct RenderScene {
  const TriangleMesh* mesh = nullptr;  // may be null
  const PointCloud* cloud = nullptr;   // may be null
  std::vector<LabelledPoint> points;
  std::vector<Polyline> polylines;
};

struct RenderOptions {
  std::vector<View> views = {View::kFront, View::kRight};  // left to right
  int height_px = 900;                                     // picture height (> 64)
  double margin_mm = 60;                                   // empty space around the geometry
  Rgb background = {255, 255, 255};
  Rgb surface = {214, 196, 178};  // mesh colour (and cloud colour)
  double point_radius_px = 0;     // cloud splat radius; 0 = from the cloud's spacing
  bool label_points = true;
  int label_font_px = 13;  // label text height
  std::string title;       // drawn at the top left; empty = none
  // The region to show (body frame, mm); empty (default) = fit the scene.
  // Give the same bounds to several pictures to draw them at one scale
  // (geometry outside is clipped).
  Eigen::AlignedBox3d bounds;
  // Throws InputError for values out of range.
  void Check() const;
};

// An RGB picture, row-major, 3 bytes per pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
};

RgbImage Render(const RenderOptions& options, const RenderScene& scene);

// Pictures side by side (top-aligned, background-filled), `gap_px` apart.
RgbImage SideBySide(const std::vector<RgbImage>& images, int gap_px = 8,
                    Rgb background = {255, 255, 255});

// Writes a PNG atomically.
void WritePng(const RgbImage& image, const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_RENDER_RENDER_H_
