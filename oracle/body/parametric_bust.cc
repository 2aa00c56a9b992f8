// The parametric body's breasts: the cleavage between the bust points
// (CarveCleavage, parametric_build.h).
#include <algorithm>
#include <cmath>

#include "oracle/body/parametric_build.h"
#include "scanners/core/errors.h"

namespace bespoke::parametric {
namespace {

double SmoothStep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Share of the cleavage's depth at height z (mm): 0 at the under-bust
// level, 1 at the bust level, 0 again `above` mm higher.
double Window(double z, double z_under_bust, double z_bust, double above) {
  if (z <= z_bust) return SmoothStep((z - z_under_bust) / (z_bust - z_under_bust));
  return 1 - SmoothStep((z - z_bust) / above);
}

}  // namespace

void CarveCleavage(const std::vector<BodyPart>& part, Build* b) {
  const BodyLayout& L = *b->layout;
  const ParametricBodyOptions& o = L.options;
  const Section bust = InterpolateSection(L.torso, L.z_bust);
  const double depth_mm =
      std::clamp(0.25 * (o.bust_girth_mm - o.under_bust_girth_mm), 0.0, 0.4 * bust.front.b);
  b->derived["cleavage_depth_mm"] = depth_mm;
  // Above the bust the cleavage fades out before the armpit level (the chest
  // girth's ring stays the chest's section).
  const double below = L.z_bust - L.z_under_bust,
               above = std::min(0.6 * below, L.z_armpit - L.z_bust);
  BESPOKE_CHECK(below > 0, "parametric body: the bust is not above the under-bust");
  for (int v = 0; v < b->mesh.num_vertices(); ++v) {
    if (part[static_cast<size_t>(v)] != BodyPart::kTorso) continue;
    Eigen::Vector3d p = b->mesh.position(v);
    if (p.z() <= L.z_under_bust || p.z() >= L.z_bust + above) continue;
    const Section s = InterpolateSection(L.torso, p.z());
    if (p.y() <= s.cv || s.front.w <= 0) continue;
    const double u = std::abs(p.x() - s.cu) / s.front.w;
    if (u >= 1) continue;
    const double shape = (1 - u * u) * (1 - u * u);
    p.y() -= depth_mm * shape * Window(p.z(), L.z_under_bust, L.z_bust, above);
    b->mesh.Move(v, p);
  }
}

}  // namespace bespoke::parametric
