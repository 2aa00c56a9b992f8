#include "scanners/render/render.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Screen coordinates (mm, y up) and depth (larger = nearer the viewer).
struct Projected {
  double sx, sy, depth;
};

Projected Project(View view, const Eigen::Vector3d& p) {
  switch (view) {
    case View::kFront:
      return {-p.x(), p.z(), p.y()};
    case View::kBack:
      return {p.x(), p.z(), -p.y()};
    case View::kRight:
      return {p.y(), p.z(), p.x()};
    case View::kLeft:
      return {-p.y(), p.z(), -p.x()};
    default:
      return {p.x(), p.y(), p.z()};
  }
}

Eigen::Vector3d TowardsViewer(View view) {
  switch (view) {
    case View::kFront:
      return Eigen::Vector3d::UnitY();
    case View::kBack:
      return -Eigen::Vector3d::UnitY();
    case View::kRight:
      return Eigen::Vector3d::UnitX();
    case View::kLeft:
      return -Eigen::Vector3d::UnitX();
    default:
      return Eigen::Vector3d::UnitZ();
  }
}

cv::Scalar Bgr(const Rgb& c, double shade = 1.0) {
  return cv::Scalar(std::clamp(c[2] * shade, 0.0, 255.0), std::clamp(c[1] * shade, 0.0, 255.0),
                    std::clamp(c[0] * shade, 0.0, 255.0));
}

// One view: its screen box in mm and the pixel mapping.
struct Canvas {
  View view;
  double min_x, max_x, min_y, max_y;  // screen box (mm), margins included
  double scale;                       // pixels per mm
  int top;                            // pixel row of max_y
  int width() const { return static_cast<int>(std::ceil((max_x - min_x) * scale)); }
  cv::Point2d Pixel(const Projected& p) const {
    return {(p.sx - min_x) * scale, top + (max_y - p.sy) * scale};
  }
};

template <typename F>
void ForEachPoint(const RenderScene& scene, F&& f) {
  if (scene.mesh) {
    for (Eigen::Index v = 0; v < scene.mesh->num_vertices(); ++v)
      f(scene.mesh->vertices.row(v).transpose());
  }
  if (scene.cloud) {
    for (Eigen::Index v = 0; v < scene.cloud->size(); ++v)
      f(scene.cloud->points.row(v).transpose());
  }
  for (const LabelledPoint& p : scene.points) f(p.position);
  for (const Polyline& l : scene.polylines) {
    for (Eigen::Index k = 0; k < l.points.rows(); ++k) f(l.points.row(k).transpose());
  }
}

void DrawMesh(const RenderOptions& o, const TriangleMesh& mesh, const Canvas& c, cv::Mat* image,
              cv::Mat* depth) {
  const Eigen::Vector3d towards = TowardsViewer(c.view);
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)),
                          b = mesh.vertices.row(mesh.faces(f, 1)),
                          d = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::Vector3d n = (b - a).cross(d - a);
    const double area = n.norm();
    if (area == 0) continue;
    const double shade = 0.28 + 0.72 * std::abs(n.dot(towards)) / area;
    const Projected p[3] = {Project(c.view, a), Project(c.view, b), Project(c.view, d)};
    cv::Point2d q[3];
    for (int k = 0; k < 3; ++k) q[k] = c.Pixel(p[k]);
    const double det =
        (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
    if (std::abs(det) < 1e-12) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({q[0].x, q[1].x, q[2].x}))));
    const int x1 =
        std::min(image->cols - 1, static_cast<int>(std::ceil(std::max({q[0].x, q[1].x, q[2].x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({q[0].y, q[1].y, q[2].y}))));
    const int y1 =
        std::min(image->rows - 1, static_cast<int>(std::ceil(std::max({q[0].y, q[1].y, q[2].y}))));
    const cv::Vec3b color(static_cast<uchar>(std::min(255.0, o.surface[2] * shade)),
                          static_cast<uchar>(std::min(255.0, o.surface[1] * shade)),
                          static_cast<uchar>(std::min(255.0, o.surface[0] * shade)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w1 =
            ((px - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (py - q[0].y)) / det;
        const double w2 =
            ((q[1].x - q[0].x) * (py - q[0].y) - (px - q[0].x) * (q[1].y - q[0].y)) / det;
        const double w0 = 1 - w1 - w2;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const float z = static_cast<float>(w0 * p[0].depth + w1 * p[1].depth + w2 * p[2].depth);
        float& zb = depth->at<float>(y, x);
        if (z <= zb) continue;
        zb = z;
        image->at<cv::Vec3b>(y, x) = color;
      }
    }
  }
}

void DrawCloud(const RenderOptions& o, const PointCloud& cloud, const Canvas& c, double radius_px,
               cv::Mat* image, cv::Mat* depth) {
  const Eigen::Vector3d towards = TowardsViewer(c.view);
  double near = -std::numeric_limits<double>::infinity(),
         far = std::numeric_limits<double>::infinity();
  if (!cloud.has_normals()) {
    for (Eigen::Index i = 0; i < cloud.size(); ++i) {
      const double d = Project(c.view, cloud.points.row(i).transpose()).depth;
      near = std::max(near, d);
      far = std::min(far, d);
    }
  }
  const int r = std::max(0, static_cast<int>(std::floor(radius_px)));
  for (Eigen::Index i = 0; i < cloud.size(); ++i) {
    double shade;
    if (cloud.has_normals()) {
      const double facing = cloud.normals.row(i).dot(towards);
      if (facing < -0.1) continue;  // the back of the surface, seen through holes
      shade = 0.3 + 0.7 * std::abs(facing);
    } else {
      const double d = Project(c.view, cloud.points.row(i).transpose()).depth;
      shade = near > far ? 0.35 + 0.65 * (d - far) / (near - far) : 1.0;
    }
    const Projected p = Project(c.view, cloud.points.row(i).transpose());
    const cv::Point2d q = c.Pixel(p);
    const cv::Vec3b color(static_cast<uchar>(std::min(255.0, o.surface[2] * shade)),
                          static_cast<uchar>(std::min(255.0, o.surface[1] * shade)),
                          static_cast<uchar>(std::min(255.0, o.surface[0] * shade)));
    const int cx = static_cast<int>(q.x), cy = static_cast<int>(q.y);
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (dx * dx + dy * dy > r * r + r) continue;
        const int x = cx + dx, y = cy + dy;
        if (x < 0 || y < 0 || x >= image->cols || y >= image->rows) continue;
        float& zb = depth->at<float>(y, x);
        if (p.depth <= zb) continue;
        zb = static_cast<float>(p.depth);
        image->at<cv::Vec3b>(y, x) = color;
      }
    }
  }
}

void DrawOverlays(const RenderOptions& o, const RenderScene& scene, const Canvas& c,
                  const cv::Mat& depth, cv::Mat* image) {
  for (const Polyline& line : scene.polylines) {
    std::vector<cv::Point> pts;
    for (Eigen::Index k = 0; k < line.points.rows(); ++k) {
      const cv::Point2d q = c.Pixel(Project(c.view, line.points.row(k).transpose()));
      pts.emplace_back(static_cast<int>(std::lround(q.x * 16)),
                       static_cast<int>(std::lround(q.y * 16)));
    }
    if (pts.size() >= 2) {
      cv::polylines(*image, std::vector<std::vector<cv::Point>>{pts}, line.closed, Bgr(line.color),
                    std::max(1, static_cast<int>(std::lround(line.width_px))), cv::LINE_AA, 4);
    }
  }
  const double font = o.label_font_px / 22.0;
  for (const LabelledPoint& point : scene.points) {
    const Projected p = Project(c.view, point.position);
    const cv::Point2d q = c.Pixel(p);
    const int x = static_cast<int>(q.x), y = static_cast<int>(q.y);
    bool hidden = false;
    if (x >= 0 && y >= 0 && x < depth.cols && y < depth.rows)
      hidden = p.depth < depth.at<float>(y, x) - 8.0;
    const cv::Point centre(x, y);
    cv::circle(*image, centre, 4, Bgr(point.color), hidden ? 1 : cv::FILLED, cv::LINE_AA);
    if (o.label_points && !point.label.empty() && !hidden) {
      cv::putText(*image, point.label, centre + cv::Point(6, -4), cv::FONT_HERSHEY_SIMPLEX, font,
                  Bgr(point.color, 0.8), 1, cv::LINE_AA);
    }
  }
}

}  // namespace

void RenderOptions::Check() const {
  if (views.empty()) throw InputError("render: no views");
  if (height_px < 64 || height_px > 20000)
    throw InputError("render: height_px must be in [64, 20000]");
  if (!(margin_mm >= 0)) throw InputError("render: margin_mm must be >= 0");
  if (!(point_radius_px >= 0 && point_radius_px < 50))
    throw InputError("render: point_radius_px must be in [0, 50)");
  if (label_font_px < 6 || label_font_px > 200)
    throw InputError("render: label_font_px must be in [6, 200]");
}

RgbImage Render(const RenderOptions& options, const RenderScene& scene) {
  options.Check();
  const int title_px = options.title.empty() ? 0 : options.label_font_px * 2 + 8;
  std::vector<Canvas> canvases;
  double extent_y = 0;
  bool any = false;
  for (View view : options.views) {
    Canvas c{view, 1e300, -1e300, 1e300, -1e300, 1.0, title_px};
    const auto grow = [&c, view](const Eigen::Vector3d& p) {
      const Projected q = Project(view, p);
      c.min_x = std::min(c.min_x, q.sx);
      c.max_x = std::max(c.max_x, q.sx);
      c.min_y = std::min(c.min_y, q.sy);
      c.max_y = std::max(c.max_y, q.sy);
    };
    ForEachPoint(scene, [&](const Eigen::Vector3d& p) {
      if (!p.allFinite()) throw InputError("render: the scene has a point that is not finite");
      if (options.bounds.isEmpty()) grow(p);
      any = true;
    });
    if (!options.bounds.isEmpty()) {
      for (int k = 0; k < 8; ++k)
        grow(options.bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)));
    }
    if (!any) throw InputError("render: nothing to draw (no mesh, cloud, points or lines)");
    c.min_x -= options.margin_mm;
    c.max_x += options.margin_mm;
    c.min_y -= options.margin_mm;
    c.max_y += options.margin_mm;
    extent_y = std::max(extent_y, c.max_y - c.min_y);
    canvases.push_back(c);
  }
  const double scale = (options.height_px - title_px) / extent_y;
  int width = 0;
  for (Canvas& c : canvases) {
    c.scale = scale;
    width += c.width();
  }
  cv::Mat image(options.height_px, width, CV_8UC3, Bgr(options.background));
  double radius = options.point_radius_px;
  if (radius == 0 && scene.cloud && !scene.cloud->empty()) {
    // Spacing of the points on a box around the bulk of the cloud (5th-95th
    // percentile per axis, so that outliers do not inflate it).
    Eigen::Vector3d e;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> v(scene.cloud->points.col(axis).data(),
                            scene.cloud->points.col(axis).data() + scene.cloud->size());
      const size_t lo = v.size() / 20, hi = v.size() - 1 - v.size() / 20;
      std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(lo), v.end());
      const double a = v[lo];
      std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(hi), v.end());
      e[axis] = std::max(v[hi] - a, 1e-9);
    }
    const double area = 2 * (e.x() * e.z() + e.y() * e.z() + e.x() * e.y());
    radius = std::max(1.0, 0.7 * std::sqrt(area / scene.cloud->size()) * scale);
  }
  int left = 0;
  for (const Canvas& c : canvases) {
    cv::Mat view = image(cv::Rect(left, 0, c.width(), options.height_px));
    cv::Mat depth(options.height_px, c.width(), CV_32F,
                  cv::Scalar(-std::numeric_limits<float>::infinity()));
    if (scene.mesh) DrawMesh(options, *scene.mesh, c, &view, &depth);
    if (scene.cloud) DrawCloud(options, *scene.cloud, c, radius, &view, &depth);
    DrawOverlays(options, scene, c, depth, &view);
    left += c.width();
  }
  if (!options.title.empty()) {
    cv::putText(image, options.title, cv::Point(8, options.label_font_px + 10),
                cv::FONT_HERSHEY_SIMPLEX, options.label_font_px / 16.0, cv::Scalar(40, 40, 40), 1,
                cv::LINE_AA);
  }
  cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
  RgbImage out;
  out.width = image.cols;
  out.height = image.rows;
  out.rgb.assign(image.data, image.data + image.total() * 3);
  return out;
}

RgbImage SideBySide(const std::vector<RgbImage>& images, int gap_px, Rgb background) {
  RgbImage out;
  for (const RgbImage& im : images) {
    out.width += im.width;
    out.height = std::max(out.height, im.height);
  }
  if (images.empty()) return out;
  out.width += gap_px * static_cast<int>(images.size() - 1);
  out.rgb.resize(static_cast<size_t>(out.width) * out.height * 3);
  for (size_t i = 0; i < out.rgb.size(); i += 3)
    std::copy(background.begin(), background.end(),
              out.rgb.begin() + static_cast<std::ptrdiff_t>(i));
  int left = 0;
  for (const RgbImage& im : images) {
    for (int y = 0; y < im.height; ++y) {
      std::copy_n(im.rgb.begin() + static_cast<std::ptrdiff_t>(y) * im.width * 3, im.width * 3,
                  out.rgb.begin() + (static_cast<std::ptrdiff_t>(y) * out.width + left) * 3);
    }
    left += im.width + gap_px;
  }
  return out;
}

// PNG encoding by cairo, which the charts use already: OpenCV's imgcodecs
// would pull GDAL and its hundred libraries into every program's start-up.
void WritePng(const RgbImage& image, const std::filesystem::path& file) {
  if (file.extension() != ".png") throw InputError(file, "the picture must be a .png file");
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3) {
    throw InternalError("WritePng: empty or inconsistent image");
  }
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height),
      &cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw InternalError("WritePng: no " + std::to_string(image.width) + " x " +
                        std::to_string(image.height) + " image surface");
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < image.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    const std::uint8_t* in = image.rgb.data() + static_cast<size_t>(y) * image.width * 3;
    for (int x = 0; x < image.width; ++x, in += 3)  // RGB24: 0x00RRGGBB, native endian
      row[x] = (std::uint32_t{in[0]} << 16) | (std::uint32_t{in[1]} << 8) | in[2];
  }
  cairo_surface_mark_dirty(surface.get());
  std::string bytes;
  const auto append = [](void* closure, const unsigned char* chunk, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(chunk), length);
    return CAIRO_STATUS_SUCCESS;
  };
  if (cairo_surface_write_to_png_stream(surface.get(), append, &bytes) != CAIRO_STATUS_SUCCESS)
    throw InternalError("PNG encoding failed for " + file.string());
  WriteFileAtomically(file, bytes);
}

}  // namespace bespoke
