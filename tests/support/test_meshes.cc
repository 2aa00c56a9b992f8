#include "tests/support/test_meshes.h"

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace bespoke::testing {

TriangleMesh Icosphere(double radius_mm, int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                    {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                    {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : v) p.normalize();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[static_cast<size_t>(a)] + v[static_cast<size_t>(b)]).normalized());
      const int id = static_cast<int>(v.size()) - 1;
      mid[key] = id;
      return id;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& face : f) {
      const int a = midpoint(face[0], face[1]), b = midpoint(face[1], face[2]),
                c = midpoint(face[2], face[0]);
      next.push_back({face[0], a, c});
      next.push_back({face[1], b, a});
      next.push_back({face[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (size_t i = 0; i < v.size(); ++i)
    mesh.vertices.row(static_cast<Eigen::Index>(i)) = radius_mm * v[i].transpose();
  mesh.faces.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (size_t i = 0; i < f.size(); ++i)
    mesh.faces.row(static_cast<Eigen::Index>(i)) = f[i].transpose();
  return mesh;
}

TriangleMesh Tube(double radius_mm, double height_mm, int around, int rings) {
  TriangleMesh mesh;
  mesh.vertices.resize(around * rings, 3);
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double angle = 2 * M_PI * i / around;
      mesh.vertices.row(j * around + i) << radius_mm * std::cos(angle), radius_mm * std::sin(angle),
          height_mm * j / (rings - 1);
    }
  mesh.faces.resize(2 * around * (rings - 1), 3);
  int row = 0;
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const int a = j * around + i, b = j * around + (i + 1) % around;
      const int c = a + around, d = b + around;
      mesh.faces.row(row++) << a, b, d;
      mesh.faces.row(row++) << a, d, c;
    }
  return mesh;
}

double TubeDistance(double radius_mm, double height_mm, int around, int rings, int a, int b) {
  const double side = 2 * radius_mm * std::sin(M_PI / around);
  int di = std::abs(a % around - b % around);
  di = std::min(di, around - di);
  const double dz = height_mm * std::abs(a / around - b / around) / (rings - 1);
  return std::hypot(di * side, dz);
}

TriangleMesh FlatGrid(int nx, int ny, double spacing_mm, double jitter) {
  TriangleMesh mesh;
  mesh.vertices.resize(nx * ny, 3);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const bool inner = i > 0 && j > 0 && i + 1 < nx && j + 1 < ny;
      const double jx = inner ? jitter * std::sin(12.9898 * i + 78.233 * j) : 0;
      const double jy = inner ? jitter * std::cos(39.3468 * i + 11.135 * j) : 0;
      mesh.vertices.row(j * nx + i) << spacing_mm * (i + jx), spacing_mm * (j + jy), 0;
    }
  mesh.faces.resize(2 * (nx - 1) * (ny - 1), 3);
  int row = 0;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      mesh.faces.row(row++) << a, b, d;
      mesh.faces.row(row++) << a, d, c;
    }
  return mesh;
}

}  // namespace bespoke::testing
