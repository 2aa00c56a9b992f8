#include "oracle/body/mesh_builder.h"

#include <cstdint>
#include <unordered_map>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

std::uint64_t EdgeKey(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace

int MeshBuilder::Add(const Eigen::Vector3d& position) {
  BESPOKE_CHECK(position.allFinite(), "mesh builder: vertex not finite");
  vertices_.push_back(position);
  return static_cast<int>(vertices_.size()) - 1;
}

void MeshBuilder::Move(int vertex, const Eigen::Vector3d& position) {
  BESPOKE_CHECK(position.allFinite(), "mesh builder: vertex not finite");
  vertices_.at(static_cast<size_t>(vertex)) = position;
}

std::vector<int> MeshBuilder::AddRing(const std::vector<Eigen::Vector3d>& positions) {
  std::vector<int> ring;
  ring.reserve(positions.size());
  for (const Eigen::Vector3d& p : positions) ring.push_back(Add(p));
  return ring;
}

void MeshBuilder::Triangle(int a, int b, int c) {
  BESPOKE_CHECK(a != b && b != c && a != c, "mesh builder: degenerate triangle");
  faces_.push_back({a, b, c});
}

void MeshBuilder::Quad(int a, int b, int c, int d) {
  if ((position(a) - position(c)).squaredNorm() <= (position(b) - position(d)).squaredNorm()) {
    Triangle(a, b, c);
    Triangle(a, c, d);
  } else {
    Triangle(a, b, d);
    Triangle(b, c, d);
  }
}

void MeshBuilder::Stitch(const std::vector<int>& r0, const std::vector<int>& r1) {
  BESPOKE_CHECK(r0.size() == r1.size() && r0.size() >= 3, "mesh builder: rings differ in length");
  const size_t n = r0.size();
  for (size_t m = 0; m < n; ++m) {
    const size_t next = (m + 1) % n;
    Quad(r0[m], r0[next], r1[next], r1[m]);
  }
}

void MeshBuilder::Fan(const std::vector<int>& ring, int pole) {
  const size_t n = ring.size();
  for (size_t m = 0; m < n; ++m) Triangle(ring[m], ring[(m + 1) % n], pole);
}

void MeshBuilder::OrientPatchLike(size_t first) {
  std::unordered_map<std::uint64_t, size_t> before;
  for (size_t f = 0; f < first; ++f) {
    for (int e = 0; e < 3; ++e) before[EdgeKey(faces_[f][e], faces_[f][(e + 1) % 3])] = f;
  }
  int agree = 0, disagree = 0;
  for (size_t f = first; f < faces_.size(); ++f) {
    for (int e = 0; e < 3; ++e) {
      const int a = faces_[f][e], b = faces_[f][(e + 1) % 3];
      if (before.count(EdgeKey(b, a))) ++agree;     // opposite direction: consistent
      if (before.count(EdgeKey(a, b))) ++disagree;  // same direction: flipped
    }
  }
  BESPOKE_CHECK(agree + disagree > 0, "mesh builder: patch shares no edge with the mesh");
  BESPOKE_CHECK(agree == 0 || disagree == 0, "mesh builder: patch orientation is mixed");
  if (disagree > 0) {
    for (size_t f = first; f < faces_.size(); ++f) std::swap(faces_[f][1], faces_[f][2]);
  }
}

void MeshBuilder::SplitEdges(
    const std::vector<std::pair<std::pair<int, int>, std::vector<int>>>& splits) {
  std::unordered_map<std::uint64_t, size_t>
      split_of;  // directed edge -> index into splits (both directions)
  for (size_t k = 0; k < splits.size(); ++k) {
    const auto [a, b] = splits[k].first;
    split_of[EdgeKey(a, b)] = k;
    split_of[EdgeKey(b, a)] = k;
  }
  std::vector<std::array<int, 3>> out;
  out.reserve(faces_.size() + 4 * splits.size());
  std::vector<int> uses(splits.size(), 0);
  for (const auto& f : faces_) {
    int hit = -1;
    for (int e = 0; e < 3; ++e) {
      if (split_of.count(EdgeKey(f[e], f[(e + 1) % 3]))) {
        BESPOKE_CHECK(hit < 0, "mesh builder: a face has two split edges");
        hit = e;
      }
    }
    if (hit < 0) {
      out.push_back(f);
      continue;
    }
    const int a = f[hit], b = f[(hit + 1) % 3], c = f[(hit + 2) % 3];
    const size_t k = split_of.at(EdgeKey(a, b));
    ++uses[k];
    // The chain from a to b along this face's direction of the edge.
    std::vector<int> chain = {a};
    const std::vector<int>& inner = splits[k].second;
    if (splits[k].first.first == a)
      chain.insert(chain.end(), inner.begin(), inner.end());
    else
      chain.insert(chain.end(), inner.rbegin(), inner.rend());
    chain.push_back(b);
    for (size_t i = 0; i + 1 < chain.size(); ++i) out.push_back({chain[i], chain[i + 1], c});
  }
  for (int u : uses)
    BESPOKE_CHECK(u == 2, "mesh builder: a split edge is not shared by exactly two faces");
  faces_ = std::move(out);
}

void MeshBuilder::FlipAll() {
  for (auto& f : faces_) std::swap(f[1], f[2]);
}

TriangleMesh MeshBuilder::Build() const {
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(vertices_.size()), 3);
  for (size_t v = 0; v < vertices_.size(); ++v)
    mesh.vertices.row(static_cast<Eigen::Index>(v)) = vertices_[v];
  mesh.faces.resize(static_cast<Eigen::Index>(faces_.size()), 3);
  for (size_t f = 0; f < faces_.size(); ++f) {
    mesh.faces.row(static_cast<Eigen::Index>(f)) << faces_[f][0], faces_[f][1], faces_[f][2];
  }
  return mesh;
}

}  // namespace bespoke
