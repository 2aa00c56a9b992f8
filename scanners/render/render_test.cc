#include "scanners/render/render.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

// A closed box from (-100, -50, 0) to (100, 50, 400), faces outwards.
TriangleMesh Box() {
  TriangleMesh m;
  m.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    m.vertices.row(i) << (i & 1 ? 100 : -100), (i & 2 ? 50 : -50), (i & 4 ? 400 : 0);
  m.faces.resize(12, 3);
  m.faces << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4,
      6, 1, 3, 5, 3, 7, 5;
  return m;
}

std::array<std::uint8_t, 3> Pixel(const RgbImage& im, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * im.width + x) * 3;
  return {im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}

TEST(Render, FrontAndSideViewsShareOneScale) {
  const TriangleMesh box = Box();
  RenderScene scene;
  scene.mesh = &box;
  RenderOptions o;
  o.height_px = 520;
  o.margin_mm = 60;
  const RgbImage im = Render(o, scene);
  // Scale: 520 px over 400 + 2 * 60 mm = 1 px/mm. Front view 200 + 120 px
  // wide, side view 100 + 120 px wide.
  EXPECT_EQ(im.height, 520);
  EXPECT_EQ(im.width, 320 + 220);
  EXPECT_EQ(Pixel(im, 2, 2), (std::array<std::uint8_t, 3>{255, 255, 255}));
  // The box's front face, seen head-on, is fully lit: the surface colour.
  EXPECT_EQ(Pixel(im, 160, 260), (std::array<std::uint8_t, 3>{214, 196, 178}));
  // Beside the box in the front view: background.
  EXPECT_EQ(Pixel(im, 40, 260), (std::array<std::uint8_t, 3>{255, 255, 255}));
}

TEST(Render, CloudsAndOverlaysAreDrawn) {
  PointCloud cloud;
  cloud.points.resize(2000, 3);
  for (int i = 0; i < 2000; ++i) cloud.points.row(i) << (i % 40) * 5.0 - 100, 0, (i / 40) * 8.0;
  RenderScene scene;
  scene.cloud = &cloud;
  scene.points.push_back({"p", Eigen::Vector3d(0, 0, 200), {255, 0, 0}});
  Polyline line;
  line.points.resize(2, 3);
  line.points << -100, 0, 100, 100, 0, 100;
  line.color = {0, 0, 255};
  scene.polylines.push_back(line);
  RenderOptions o;
  o.views = {View::kFront};
  o.label_points = false;
  const RgbImage im = Render(o, scene);
  int red = 0, blue = 0, grey = 0;
  for (size_t i = 0; i < im.rgb.size(); i += 3) {
    red += im.rgb[i] > 200 && im.rgb[i + 1] < 80 && im.rgb[i + 2] < 80;
    blue += im.rgb[i] < 80 && im.rgb[i + 1] < 80 && im.rgb[i + 2] > 200;
    grey += im.rgb[i] < 240 && im.rgb[i] > 60 && im.rgb[i + 1] < 230 && im.rgb[i + 1] > 60;
  }
  EXPECT_GT(red, 20);
  EXPECT_GT(blue, 100);
  EXPECT_GT(grey, 1000);
}

TEST(Render, WritesPngAndRejectsBadInput) {
  testing::TempDir dir;
  const TriangleMesh box = Box();
  RenderScene scene;
  scene.mesh = &box;
  const RgbImage im = Render(RenderOptions(), scene);
  WritePng(im, dir / "box.png");
  std::ifstream in(dir / "box.png", std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_THROW(WritePng(im, dir / "box.jpg"), InputError);
  EXPECT_THROW(WritePng(im, dir / "missing" / "box.png"), InputError);
  EXPECT_THROW(Render(RenderOptions(), RenderScene()), InputError);
  const RgbImage two = SideBySide({im, im}, 10);
  EXPECT_EQ(two.width, 2 * im.width + 10);
}

// Every pixel comes back from the file as written (read by cairo's decoder).
TEST(Render, PngKeepsEveryPixel) {
  testing::TempDir dir;
  RgbImage im;
  im.width = 5;
  im.height = 3;
  for (int i = 0; i < im.width * im.height; ++i)
    for (int c = 0; c < 3; ++c)
      im.rgb.push_back(static_cast<std::uint8_t>((i * 37 + c * 91) % 256));
  const std::string file = (dir / "pixels.png").string();
  WritePng(im, file);
  cairo_surface_t* read = cairo_image_surface_create_from_png(file.c_str());
  ASSERT_EQ(cairo_surface_status(read), CAIRO_STATUS_SUCCESS);
  ASSERT_EQ(cairo_image_surface_get_width(read), im.width);
  ASSERT_EQ(cairo_image_surface_get_height(read), im.height);
  const unsigned char* data = cairo_image_surface_get_data(read);
  const int stride = cairo_image_surface_get_stride(read);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint32_t argb = reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];
      const std::uint8_t* rgb = &im.rgb[static_cast<size_t>(y * im.width + x) * 3];
      EXPECT_EQ((argb >> 16) & 0xff, rgb[0]) << x << "," << y;
      EXPECT_EQ((argb >> 8) & 0xff, rgb[1]) << x << "," << y;
      EXPECT_EQ(argb & 0xff, rgb[2]) << x << "," << y;
    }
  cairo_surface_destroy(read);
}

}  // namespace
}  // namespace bespoke
