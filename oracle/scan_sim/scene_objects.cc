#include "oracle/scan_sim/scene_objects.h"

#include <algorithm>
#include <cmath>

#include "scanners/core/constants.h"

namespace bespoke {
namespace {

// A closed prism over a convex polygon `outline` (counter-clockwise from
// above) from z = 0 to `height`, faces outwards.
TriangleMesh Prism(const std::vector<Eigen::Vector2d>& outline, double height) {
  const int n = static_cast<int>(outline.size());
  TriangleMesh m;
  m.vertices.resize(2 * n + 2, 3);
  for (int i = 0; i < n; ++i) {
    m.vertices.row(i) << outline[static_cast<size_t>(i)].x(), outline[static_cast<size_t>(i)].y(),
        0;
    m.vertices.row(n + i) << outline[static_cast<size_t>(i)].x(),
        outline[static_cast<size_t>(i)].y(), height;
  }
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : outline) c += p / n;
  m.vertices.row(2 * n) << c.x(), c.y(), 0;
  m.vertices.row(2 * n + 1) << c.x(), c.y(), height;
  m.faces.resize(4 * n, 3);
  for (int i = 0, f = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.faces.row(f++) << i, j, n + j;
    m.faces.row(f++) << i, n + j, n + i;
    m.faces.row(f++) << 2 * n, j, i;              // bottom, facing down
    m.faces.row(f++) << 2 * n + 1, n + i, n + j;  // top, facing up
  }
  return m;
}

// Smallest horizontal distance from the outline's centre disc (radius
// `reach`) to body vertices below `height`, and to earlier objects.
bool IsFree(const TriangleMesh& body, const std::vector<std::pair<Eigen::Vector2d, double>>& taken,
            const Eigen::Vector2d& centre, double reach, double height) {
  for (const auto& [c, r] : taken) {
    if ((c - centre).norm() < r + reach + 80) return false;
  }
  for (Eigen::Index v = 0; v < body.num_vertices(); ++v) {
    if (body.vertices(v, 2) > height + 80) continue;
    if ((body.vertices.row(v).head<2>().transpose() - centre).norm() < reach + 80) return false;
  }
  return true;
}

}  // namespace

TriangleMesh FloorPatch(double half_size_mm) {
  const int cells = std::max(1, static_cast<int>(std::ceil(2 * half_size_mm / 100)));
  TriangleMesh m;
  m.vertices.resize((cells + 1) * (cells + 1), 3);
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      m.vertices.row(j * (cells + 1) + i) << -half_size_mm + 2 * half_size_mm * i / cells,
          -half_size_mm + 2 * half_size_mm * j / cells, 0;
    }
  }
  m.faces.resize(2 * cells * cells, 3);
  for (int j = 0, f = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const int a = j * (cells + 1) + i, b = a + 1, c = a + cells + 2, d = a + cells + 1;
      m.faces.row(f++) << a, b, c;  // counter-clockwise from above: normal +z
      m.faces.row(f++) << a, c, d;
    }
  }
  return m;
}

std::vector<TriangleMesh> PlaceStrayObjects(const TriangleMesh& body, int count,
                                            double booth_radius_mm, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<TriangleMesh> out;
  std::vector<std::pair<Eigen::Vector2d, double>> taken;
  for (int k = 0; k < count; ++k) {
    const bool pole = k % 2 == 0;
    for (int attempt = 0; attempt < 200; ++attempt) {
      const double azimuth = 2 * kPi * unit(rng);
      const double distance = booth_radius_mm * (0.45 + 0.3 * unit(rng));
      const Eigen::Vector2d centre(distance * std::cos(azimuth), distance * std::sin(azimuth));
      std::vector<Eigen::Vector2d> outline;
      double reach, height;
      if (pole) {
        const double r = 15 + 15 * unit(rng);
        height = 900 + 1000 * unit(rng);
        reach = r;
        for (int i = 0; i < 24; ++i) {
          const double a = 2 * kPi * i / 24;
          outline.push_back(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
        }
      } else {
        const double w = 250 + 200 * unit(rng), d = 250 + 200 * unit(rng), turn = kPi * unit(rng);
        height = 300 + 700 * unit(rng);
        reach = 0.5 * std::hypot(w, d);
        const Eigen::Rotation2Dd rot(turn);
        for (const auto& corner : {Eigen::Vector2d(w, d), Eigen::Vector2d(-w, d),
                                   Eigen::Vector2d(-w, -d), Eigen::Vector2d(w, -d)}) {
          outline.push_back(centre + rot * (0.5 * corner));
        }
      }
      if (!IsFree(body, taken, centre, reach, height)) continue;
      taken.push_back({centre, reach});
      out.push_back(Prism(outline, height));
      break;
    }
  }
  return out;
}

}  // namespace bespoke
