#include "oracle/scene/synthetic_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "scanners/core/constants.h"

namespace bespoke::testing {
namespace {

using Rng = std::mt19937_64;

double Uniform(Rng& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}

Eigen::Vector3d RandomDirection(Rng& rng) {
  std::normal_distribution<double> g;
  Eigen::Vector3d d(g(rng), g(rng), g(rng));
  while (d.norm() < 1e-9) d = Eigen::Vector3d(g(rng), g(rng), g(rng));
  return d.normalized();
}

// A closed primitive: area, uniform surface samples with outward normals, and
// an inside test (with the surface pushed out by `margin`).
class Shape {
 public:
  virtual ~Shape() = default;
  virtual double Area() const = 0;
  virtual void Sample(Rng& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) const = 0;
  virtual bool Inside(const Eigen::Vector3d& p, double margin) const = 0;
};

class Capsule : public Shape {
 public:
  Capsule(Eigen::Vector3d a, Eigen::Vector3d b, double r) : a_(a), b_(b), r_(r) {}
  double Area() const override { return 2 * kPi * r_ * (b_ - a_).norm() + 4 * kPi * r_ * r_; }
  void Sample(Rng& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) const override {
    const Eigen::Vector3d axis = (b_ - a_).normalized();
    const double side = 2 * kPi * r_ * (b_ - a_).norm();
    if (Uniform(rng, 0, Area()) < side) {
      const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
      const double t = Uniform(rng, 0, 1), angle = Uniform(rng, 0, 2 * kPi);
      *n = std::cos(angle) * u + std::sin(angle) * v;
      *p = a_ + t * (b_ - a_) + r_ * *n;
    } else {
      *n = RandomDirection(rng);
      *p = (n->dot(axis) < 0 ? a_ : b_) + r_ * *n;
    }
  }
  bool Inside(const Eigen::Vector3d& p, double margin) const override {
    const Eigen::Vector3d ab = b_ - a_;
    const double t = std::clamp((p - a_).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a_ + t * ab)).norm() < r_ + margin;
  }

 private:
  Eigen::Vector3d a_, b_;
  double r_;
};

class Ellipsoid : public Shape {
 public:
  Ellipsoid(Eigen::Vector3d c, Eigen::Vector3d radii) : c_(c), r_(radii) {}
  double Area() const override {  // Knud Thomsen's approximation, < 1.1 % error
    const double p = 1.6075, a = std::pow(r_.x(), p), b = std::pow(r_.y(), p),
                 c = std::pow(r_.z(), p);
    return 4 * kPi * std::pow((a * b + a * c + b * c) / 3, 1 / p);
  }
  void Sample(Rng& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) const override {
    // Sphere directions mapped by diag(r), accepted in proportion to the
    // area stretch |det| * |M^-T d|.
    const double max_stretch = 1.0 / r_.minCoeff();
    for (;;) {
      const Eigen::Vector3d d = RandomDirection(rng);
      const Eigen::Vector3d g = d.cwiseQuotient(r_);
      if (Uniform(rng, 0, max_stretch) > g.norm()) continue;
      *p = c_ + d.cwiseProduct(r_);
      *n = g.normalized();
      return;
    }
  }
  bool Inside(const Eigen::Vector3d& p, double margin) const override {
    return ((p - c_).array() / (r_.array() + margin)).matrix().squaredNorm() < 1.0;
  }

 private:
  Eigen::Vector3d c_, r_;
};

// Axis-aligned box; the bottom face (z = low.z) is left out when `no_bottom`.
class Box : public Shape {
 public:
  Box(Eigen::Vector3d low, Eigen::Vector3d high, bool no_bottom)
      : low_(low), high_(high), no_bottom_(no_bottom) {}
  double FaceArea(int axis) const {
    const Eigen::Vector3d s = high_ - low_;
    return s((axis + 1) % 3) * s((axis + 2) % 3);
  }
  double Area() const override {
    return 2 * (FaceArea(0) + FaceArea(1) + FaceArea(2)) - (no_bottom_ ? FaceArea(2) : 0);
  }
  void Sample(Rng& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) const override {
    for (;;) {
      double pick = Uniform(rng, 0, 2 * (FaceArea(0) + FaceArea(1) + FaceArea(2)));
      int face = 0;
      while (pick > FaceArea(face / 2)) pick -= FaceArea(face / 2), ++face;
      const int axis = face / 2;
      const bool top = face % 2 == 1;
      if (no_bottom_ && axis == 2 && !top) continue;
      for (int c = 0; c < 3; ++c) (*p)(c) = Uniform(rng, low_(c), high_(c));
      (*p)(axis) = top ? high_(axis) : low_(axis);
      *n = Eigen::Vector3d::Zero();
      (*n)(axis) = top ? 1 : -1;
      return;
    }
  }
  bool Inside(const Eigen::Vector3d& p, double margin) const override {
    return (p.array() > low_.array() - margin).all() && (p.array() < high_.array() + margin).all();
  }

 private:
  Eigen::Vector3d low_, high_;
  bool no_bottom_;
};

struct Sample {
  Eigen::Vector3d p, n;
  ScenePart part;
};

// Feet pointing forward: toes 190 mm ahead of the ankle axis, heel 60 behind.
double FootCentreY(const SyntheticSceneOptions& o) { return o.feet_forward ? 65.0 : 0.0; }

std::vector<std::unique_ptr<Shape>> MakePerson(const SyntheticSceneOptions& o, double* hand_max_x) {
  std::vector<std::unique_ptr<Shape>> s;
  const double shin_y = 0.0, foot_y = FootCentreY(o);
  for (double side : {-1.0, 1.0}) {
    s.push_back(std::make_unique<Box>(Eigen::Vector3d(side * 100 - 50, foot_y - 125, 0),
                                      Eigen::Vector3d(side * 100 + 50, foot_y + 125, 70), true));
    s.push_back(std::make_unique<Capsule>(Eigen::Vector3d(side * 100, shin_y, 60),
                                          Eigen::Vector3d(side * 95, shin_y, 480), 48));
    s.push_back(std::make_unique<Capsule>(Eigen::Vector3d(side * 95, shin_y, 480),
                                          Eigen::Vector3d(side * 95, shin_y, 860), 72));
    // Arm: 30 degrees out from vertical.
    const Eigen::Vector3d dir(side * 0.5, 0, -std::sqrt(3.0) / 2);
    const Eigen::Vector3d shoulder(side * 185, shin_y, 1440);
    const Eigen::Vector3d elbow = shoulder + 300 * dir, wrist = elbow + 270 * dir;
    s.push_back(std::make_unique<Capsule>(shoulder, elbow, 45));
    s.push_back(std::make_unique<Capsule>(elbow, wrist, 38));
    const double start = o.wrist_gap_mm > 0 ? 38 + o.wrist_gap_mm + 28 : 20;
    const Eigen::Vector3d hand_a = wrist + start * dir, hand_b = hand_a + 110 * dir;
    s.push_back(std::make_unique<Capsule>(hand_a, hand_b, 28));
    if (side > 0) *hand_max_x = hand_b.x() + 28;
  }
  s.push_back(std::make_unique<Ellipsoid>(Eigen::Vector3d(0, shin_y, 1190),
                                          Eigen::Vector3d(175, 115, 390)));
  s.push_back(std::make_unique<Capsule>(Eigen::Vector3d(0, shin_y, 1500),
                                        Eigen::Vector3d(0, shin_y, 1580), 55));
  const double head_y = shin_y + (o.head_forward ? 25 : 0);
  s.push_back(
      std::make_unique<Ellipsoid>(Eigen::Vector3d(0, head_y, 1650), Eigen::Vector3d(78, 98, 100)));
  if (o.head_forward) {
    s.push_back(std::make_unique<Ellipsoid>(Eigen::Vector3d(0, head_y + 95, 1630),
                                            Eigen::Vector3d(15, 22, 25)));
  }
  return s;
}

void SampleUnion(const std::vector<std::unique_ptr<Shape>>& shapes, double spacing, Rng& rng,
                 std::vector<Sample>* out) {
  for (size_t i = 0; i < shapes.size(); ++i) {
    const auto count = static_cast<std::int64_t>(shapes[i]->Area() / (spacing * spacing));
    for (std::int64_t k = 0; k < count; ++k) {
      Sample s{{}, {}, ScenePart::kBody};
      shapes[i]->Sample(rng, &s.p, &s.n);
      bool covered = false;
      for (size_t j = 0; j < shapes.size() && !covered; ++j)
        covered = j != i && shapes[j]->Inside(s.p, 0.0);
      if (!covered) out->push_back(s);
    }
  }
}

}  // namespace

std::int64_t SyntheticScene::Count(ScenePart p) const {
  return std::count(part.begin(), part.end(), p);
}

Eigen::MatrixX3d SyntheticScene::PointsMm(ScenePart p) const {
  Eigen::MatrixX3d out(Count(p), 3);
  Eigen::Index row = 0;
  for (size_t i = 0; i < part.size(); ++i) {
    if (part[i] == p) out.row(row++) = cloud.points.row(static_cast<Eigen::Index>(i)) * mm_per_unit;
  }
  return out;
}

SyntheticScene MakeSyntheticScene(const SyntheticSceneOptions& o) {
  Rng rng(o.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  SyntheticScene scene;
  std::vector<Sample> samples;
  const auto person = MakePerson(o, &scene.right_hand_max_x_mm);
  SampleUnion(person, o.spacing_mm, rng, &samples);

  const double object_x = scene.right_hand_max_x_mm + o.object_gap_mm;
  const Box object(Eigen::Vector3d(object_x, -100, 0), Eigen::Vector3d(object_x + 200, 100, 1100),
                   true);
  if (o.second_object) {
    const auto count = static_cast<std::int64_t>(object.Area() / (o.spacing_mm * o.spacing_mm));
    for (std::int64_t k = 0; k < count; ++k) {
      Sample s{{}, {}, ScenePart::kObject};
      object.Sample(rng, &s.p, &s.n);
      samples.push_back(s);
    }
  }
  const double f = o.floor_half_size_mm;
  auto under_something = [&](const Eigen::Vector3d& p) {
    const bool under_foot =
        std::abs(std::abs(p.x()) - 100) <= 50 && std::abs(p.y() - FootCentreY(o)) <= 125;
    return under_foot || (o.second_object && object.Inside(p + Eigen::Vector3d(0, 0, 1), 0.0));
  };
  if (o.floor) {
    const auto count = static_cast<std::int64_t>(4 * f * f / (o.spacing_mm * o.spacing_mm));
    for (std::int64_t k = 0; k < count; ++k) {
      const Eigen::Vector3d p(Uniform(rng, -f, f), Uniform(rng, -f, f), 0);
      if (!under_something(p)) samples.push_back({p, Eigen::Vector3d::UnitZ(), ScenePart::kFloor});
    }
  }
  for (Sample& s : samples) s.p += o.noise_mm * noise(rng) * s.n;

  // Stray points, at least 40 mm from every surface.
  auto near_surface = [&](const Eigen::Vector3d& p) {
    for (const auto& shape : person) {
      if (shape->Inside(p, 40)) return true;
    }
    if (o.second_object && object.Inside(p, 40)) return true;
    return o.floor && std::abs(p.z()) < 40 && std::abs(p.x()) < f + 40 && std::abs(p.y()) < f + 40;
  };
  Eigen::AlignedBox3d box;
  for (const Sample& s : samples) box.extend(s.p);
  box.min() -= Eigen::Vector3d::Constant(50.0);
  box.max() += Eigen::Vector3d::Constant(50.0);
  auto stray_point = [&] {
    for (;;) {
      const Eigen::Vector3d p(Uniform(rng, box.min().x(), box.max().x()),
                              Uniform(rng, box.min().y(), box.max().y()),
                              Uniform(rng, box.min().z(), box.max().z()));
      if (!near_surface(p)) return p;
    }
  };
  for (int k = 0; k < o.isolated_outliers; ++k) {
    samples.push_back({stray_point(), Eigen::Vector3d::Zero(), ScenePart::kOutlier});
  }
  for (int k = 0; k < o.outlier_clumps; ++k) {
    const Eigen::Vector3d c = stray_point();
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d p = c + 2.0 * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      samples.push_back({p, Eigen::Vector3d::Zero(), ScenePart::kOutlier});
    }
  }

  // Shuffle so that no test can rely on the order, then map to the scanner.
  std::shuffle(samples.begin(), samples.end(), rng);
  const auto n = static_cast<Eigen::Index>(samples.size());
  scene.cloud.points.resize(n, 3);
  scene.true_normals.resize(n, 3);
  scene.part.resize(samples.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    const Sample& s = samples[static_cast<size_t>(i)];
    scene.cloud.points.row(i) = (o.scanner_from_body * s.p).transpose() / o.mm_per_unit;
    scene.true_normals.row(i) = (o.scanner_from_body.linear() * s.n).transpose();
    scene.part[static_cast<size_t>(i)] = s.part;
  }
  scene.scanner_from_body = o.scanner_from_body;
  scene.mm_per_unit = o.mm_per_unit;
  return scene;
}

Eigen::Isometry3d RandomRigid(unsigned seed, double max_translation_mm) {
  Rng rng(seed);
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  for (int c = 0; c < 3; ++c)
    t.translation()(c) = Uniform(rng, -max_translation_mm, max_translation_mm);
  return t;
}

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

}  // namespace bespoke::testing
