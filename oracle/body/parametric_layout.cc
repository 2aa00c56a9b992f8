#include "oracle/body/parametric_layout.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr int kFields = 9;
using Fields = std::array<double, kFields>;

Fields ToFields(const Section& s) {
  return {s.cu, s.cv, s.a, s.front.b, s.front.p, s.front.w, s.back.b, s.back.p, s.back.w};
}

Section FromFields(const Fields& f) {
  Section s;
  s.cu = f[0];
  s.cv = f[1];
  s.a = f[2];
  s.front = {f[3], f[4], f[5]};
  s.back = {f[6], f[7], f[8]};
  return s;
}

// Fritsch-Carlson monotone slopes at every knot.
std::vector<double> MonotoneSlopes(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = x.size();
  std::vector<double> d(n - 1), m(n, 0.0);
  for (size_t k = 0; k + 1 < n; ++k) d[k] = (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
  m[0] = d[0];
  m[n - 1] = d[n - 2];
  for (size_t k = 1; k + 1 < n; ++k) {
    if (d[k - 1] * d[k] <= 0) continue;
    const double h0 = x[k] - x[k - 1], h1 = x[k + 1] - x[k];
    const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
    m[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k]);
  }
  // Ends: keep monotone (slope zero when the first/last step is flat).
  for (size_t k : {size_t{0}, n - 1}) {
    const double dk = d[k == 0 ? 0 : n - 2];
    if (dk == 0) m[k] = 0;
  }
  return m;
}

// Solves for the front depth b so that the section's perimeter is `girth`.
void SolveFrontDepth(Section* s, double girth, const char* what) {
  double lo = 0.2 * s->a, hi = 2.5 * s->a;
  const auto perimeter_with = [s](double b) {
    Section t = *s;
    t.front.b = b;
    return t.Perimeter();
  };
  if (perimeter_with(lo) > girth || perimeter_with(hi) < girth) {
    throw InputError(
        std::string("parametric body: ") + what +
        " is not reachable with the neighbouring girths; check bust, under-bust and chest");
  }
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (perimeter_with(mid) < girth ? lo : hi) = mid;
  }
  s->front.b = 0.5 * (lo + hi);
}

// A section of relative shape (a = 1) scaled to `girth`, centred at (cu, cv).
Section Girth(double girth, double cu, double cv, SectionHalf front, SectionHalf back) {
  Section s;
  s.a = 1;
  s.front = front;
  s.back = back;
  s = s.Scaled(girth / s.Perimeter());
  s.cu = cu;
  s.cv = cv;
  return s;
}

// A section given in millimetres by its extent along v (back_v .. front_v).
Section Extent(double cu, double a, double back_v, double front_v, double p_front, double p_back) {
  Section s;
  s.cu = cu;
  s.a = a;
  s.cv = 0.5 * (back_v + front_v);
  const double half = 0.5 * (front_v - back_v);
  s.front = {half, p_front, 0};
  s.back = {half, p_back, 0};
  return s;
}

// A key whose tilted plane has its front centre at z_front and its back
// centre at z_back.
SectionKey Tilted(const Section& s, double z_front, double z_back, const std::string& girth) {
  SectionKey key;
  key.section = s;
  key.girth = girth;
  key.tilt = std::asin(std::clamp((z_back - z_front) / (s.front.b + s.back.b), -0.9, 0.9));
  key.at = z_front + s.front.b * std::sin(key.tilt);
  return key;
}

void AddTorsoKeys(BodyLayout* L) {
  const ParametricBodyOptions& o = L->options;
  const double H = o.stature_mm, k = H / 1660.0;
  auto& t = L->torso;
  t.push_back({L->z_hip, Girth(o.hip_girth_mm, 0, -15 * k, {0.66, 2.3, 0}, {0.78, 2.5, 0.30}),
               "hip_girth"});
  t.push_back({L->z_middle_hip,
               Girth(o.middle_hip_girth_mm, 0, -5 * k, {0.72, 2.2, 0}, {0.66, 2.4, 0.25}),
               "middle_hip_girth"});
  t.push_back(
      {L->z_waist, Girth(o.waist_girth_mm, 0, 0, {0.70, 2.2, 0}, {0.62, 2.4, 0.2}), "waist_girth"});
  const Section under_bust =
      Girth(o.under_bust_girth_mm, 0, 5 * k, {0.66, 2.4, 0.2}, {0.64, 2.6, 0.3});
  t.push_back({L->z_under_bust, under_bust, "under_bust_girth"});
  const Section chest = Girth(o.chest_girth_mm, 0, -5 * k, {0.62, 2.6, 0.3}, {0.66, 2.8, 0.35});
  // Bust: as wide as between under-bust and chest, the back of the chest,
  // a flat front between the bust points (the tape's line over the
  // cleavage, CarveCleavage) rounding off beyond them (exponent 2: a
  // breast's outer side, not a box's); the front depth makes the girth.
  Section bust;
  bust.cu = 0;
  bust.cv = 5 * k;
  bust.a = 0.5 * (under_bust.a + chest.a) * 1.01;
  bust.back = {0.5 * (under_bust.back.b + chest.back.b), 2.7,
               0.5 * (under_bust.back.w + chest.back.w)};
  bust.front = {bust.a * 0.7, 2.0, 0.55 * bust.a};
  SolveFrontDepth(&bust, o.bust_girth_mm, "bust_girth_mm");
  t.push_back({L->z_bust, bust, "bust_girth"});
  t.push_back({L->z_armpit, chest, "chest_girth"});
  // Shoulder (acromion level): exactly the shoulder width; thin front-back.
  const double sa = 0.5 * o.shoulder_width_mm;
  Section shoulder;
  shoulder.cv = -20 * k;
  shoulder.a = sa;
  shoulder.front = {0.34 * sa, 2.4, 0};
  shoulder.back = {0.36 * sa, 2.4, 0};
  t.push_back({L->z_shoulder, shoulder, ""});
  // Neck base: a tilted ring through the back neck point (its back centre)
  // and the front neck point (its front centre); the trapezius between.
  const Section neck = Girth(o.neck_girth_mm, 0, -25 * k, {0.92, 2.1, 0}, {1.0, 2.2, 0});
  const double neck_front = neck.cv + neck.front.b, neck_back = neck.cv - neck.back.b;
  Section trapezius = shoulder;
  trapezius.a = neck.a + 0.45 * (sa - neck.a);
  trapezius.cv = 0.5 * (shoulder.cv + neck.cv);
  trapezius.front.b = neck_front + 4 * k - trapezius.cv;
  trapezius.back.b = trapezius.cv - (neck_back - 12 * k);
  t.push_back(Tilted(trapezius, L->z_shoulder + 0.5 * (L->z_jugulare - L->z_shoulder),
                     L->z_shoulder + 0.55 * (L->z_back_neck - L->z_shoulder), ""));
  t.push_back(Tilted(neck, L->z_jugulare, L->z_back_neck, "neck_girth"));
  // Head: breadth hb, length hl; centred slightly forward of the neck.
  const double hb = 0.088 * H, hl = 0.112 * H, hc = 8 * k, head = H - L->z_chin;
  t.push_back({L->z_chin - 0.008 * H, neck.Scaled(0.96), ""});  // under the chin
  t.push_back({L->z_chin, Extent(0, 0.36 * hb, neck_back - 4 * k, hc + 0.48 * hl, 2.0, 2.2), ""});
  t.push_back({L->z_chin + 0.25 * head,
               Extent(0, 0.45 * hb, hc - 0.40 * hl, hc + 0.52 * hl, 2.2, 2.3), ""});
  t.push_back({L->z_chin + 0.45 * head,
               Extent(0, 0.50 * hb, hc - 0.50 * hl, hc + 0.50 * hl, 2.3, 2.3), ""});
  L->dome = Extent(0, 0.50 * hb, hc - 0.52 * hl, hc + 0.46 * hl, 2.2, 2.2);
  t.push_back({L->z_dome, L->dome, ""});
}

void AddLegKeys(BodyLayout* L) {
  const ParametricBodyOptions& o = L->options;
  const double H = o.stature_mm, k = H / 1660.0;
  const double xa = 0.5 * o.stance_width_mm;
  Section thigh = Girth(o.thigh_girth_mm, 0, -12 * k, {1.0, 2.1, 0}, {1.08, 2.2, 0});
  const double x_thigh = thigh.a + 0.006 * H;
  thigh.cu = x_thigh;
  const auto axis_x = [&](double z) {
    const double u = (L->z_thigh - z) / (L->z_thigh - L->z_ankle);
    return x_thigh + (xa - x_thigh) * std::clamp(u, 0.0, 1.0);
  };
  const double mid_thigh_z = L->z_thigh - 0.45 * (L->z_thigh - L->z_knee);
  auto& g = L->leg;
  // Foot: horizontal outlines from the sole up to the ankle, as extents
  // along y (heel .. toe) and half-widths, scaled with the stature.
  const double foot = 0.152 * H, heel = -0.24 * foot, toe = heel + foot, fw = 0.029 * H;
  g.push_back({0.0, Extent(xa, 0.88 * fw, heel + 10 * k, toe - 8 * k, 2.6, 2.2), ""});
  g.push_back({1.5 * k, Extent(xa, 0.95 * fw, heel + 4 * k, toe - 3 * k, 2.6, 2.2), ""});
  g.push_back({5 * k, Extent(xa, fw, heel + 1 * k, toe, 2.6, 2.3), ""});
  g.push_back({14 * k, Extent(xa, fw, heel, toe - 4 * k, 2.5, 2.3), ""});
  const double instep_low = std::min(32 * k, 0.55 * L->z_malleolus_outside);
  const double instep_high = std::min(55 * k, 0.85 * L->z_malleolus_outside);
  g.push_back({instep_low, Extent(xa, 0.93 * fw, heel, heel + 0.78 * foot, 2.4, 2.3), ""});
  g.push_back({instep_high, Extent(xa, 0.82 * fw, heel + 5 * k, heel + 0.55 * foot, 2.2, 2.2), ""});
  // Ankle: the malleoli widen the section below the ankle girth's level.
  // The ankle girth (ISO 8559-1: the minimum above the malleoli) is the
  // slimmest ring, just above the bones; the leg is 10 % wider at the outer
  // ankle bone and 7 % at the inner one.
  const Section ankle = Girth(o.ankle_girth_mm, xa, 0, {1.15, 2.2, 0}, {1.05, 2.2, 0});
  g.push_back({L->z_malleolus_outside, ankle.Scaled(1 / 0.91), ""});
  g.push_back({L->z_malleolus_inside, ankle.Scaled(0.97 / 0.91), ""});
  g.push_back({L->z_ankle, ankle, "ankle_girth"});
  g.push_back({L->z_calf,
               Girth(o.calf_girth_mm, axis_x(L->z_calf), -10 * k, {0.9, 2.1, 0}, {1.2, 2.2, 0}),
               "calf_girth"});
  const double below_knee_z = L->z_knee - 0.18 * (L->z_knee - L->z_calf);
  g.push_back(
      {below_knee_z,
       Girth(o.knee_girth_mm * 0.97, axis_x(below_knee_z), -4 * k, {0.95, 2.2, 0}, {1.0, 2.2, 0}),
       ""});
  g.push_back({L->z_knee,
               Girth(o.knee_girth_mm, axis_x(L->z_knee), 0, {1.0, 2.3, 0}, {0.95, 2.2, 0}),
               "knee_girth"});
  g.push_back({mid_thigh_z,
               Girth(0.5 * (o.thigh_girth_mm * 0.92 + o.knee_girth_mm * 1.1), axis_x(mid_thigh_z),
                     -6 * k, {1.0, 2.1, 0}, {1.04, 2.2, 0}),
               ""});
  g.push_back({L->z_thigh, thigh, "thigh_girth"});
  // Crotch lobe: a little wider than the thigh, reaching half-way between
  // the thigh's and the hip's outside, clipped at x = 0.
  const Section& hip = L->torso.front().section;
  L->lobe_rx = 1.10 * thigh.a;
  L->lobe_ry = 1.06 * 0.5 * (thigh.front.b + thigh.back.b);
  L->lobe_y = thigh.cv + 0.5 * (thigh.front.b - thigh.back.b);
  const double lateral = 0.5 * (hip.a + x_thigh + thigh.a);
  L->lobe_x = std::clamp(lateral - L->lobe_rx, 0.25 * L->lobe_rx, 0.8 * L->lobe_rx);
}

void AddArmKeys(BodyLayout* L) {
  const ParametricBodyOptions& o = L->options;
  const double H = o.stature_mm, k = H / 1660.0, len = o.arm_length_mm;
  L->arm_upper_lateral = 0.285 * len;
  L->arm_elbow_lateral = 0.57 * len;
  L->arm_wrist_lateral = len;
  const double hand = 0.108 * H;
  L->arm_tip_lateral = len + hand;
  auto& g = L->arm;
  const double ua = o.upper_arm_girth_mm;
  g.push_back({0.12 * len, Girth(1.08 * ua, 0, 0, {1.0, 2.1, 0}, {1.0, 2.1, 0}), ""});
  g.push_back(
      {L->arm_upper_lateral, Girth(ua, 0, 0, {1.0, 2.0, 0}, {1.05, 2.0, 0}), "upper_arm_girth"});
  g.push_back(
      {L->arm_elbow_lateral, Girth(0.87 * ua, 0, 0, {1.0, 2.1, 0}, {1.05, 2.1, 0}), "elbow_girth"});
  g.push_back(
      {0.70 * len,
       Girth(0.5 * (0.84 * ua + o.wrist_girth_mm * 1.1), 0, 0, {1.1, 2.1, 0}, {1.1, 2.1, 0}), ""});
  g.push_back({len, Girth(o.wrist_girth_mm, 0, 0, {1.3, 2.2, 0}, {1.3, 2.2, 0}), "wrist_girth"});
  // Hand: thin along U (palm towards the body in an A-pose), wide along F.
  const double hw = 0.0235 * H;
  g.push_back({len + 0.35 * hand, Extent(0, 13 * k, -hw, hw, 2.6, 2.6), ""});
  g.push_back({len + 0.55 * hand, Extent(0, 11 * k, -1.02 * hw, 1.02 * hw, 2.6, 2.6), ""});
  g.push_back({len + 0.80 * hand, Extent(0, 9 * k, -0.92 * hw, 0.92 * hw, 2.4, 2.4), ""});
  L->armhole_width = 0.8 * (L->z_shoulder - L->z_armpit);
}

}  // namespace

double InterpolateTilt(const std::vector<SectionKey>& keys, double at) {
  BESPOKE_CHECK(!keys.empty(), "InterpolateTilt without keys");
  if (at <= keys.front().at) return keys.front().tilt;
  if (at >= keys.back().at) return keys.back().tilt;
  size_t i = 0;
  while (keys[i + 1].at < at) ++i;
  const double t = (at - keys[i].at) / (keys[i + 1].at - keys[i].at);
  return (1 - t) * keys[i].tilt + t * keys[i + 1].tilt;
}

Section InterpolateSection(const std::vector<SectionKey>& keys, double at) {
  BESPOKE_CHECK(!keys.empty(), "InterpolateSection without keys");
  if (keys.size() == 1 || at <= keys.front().at) return keys.front().section;
  if (at >= keys.back().at) return keys.back().section;
  std::vector<double> x;
  for (const SectionKey& key : keys) x.push_back(key.at);
  const size_t i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;
  const double h = x[i + 1] - x[i], t = (at - x[i]) / h;
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  Fields out{};
  for (int f = 0; f < kFields; ++f) {
    std::vector<double> y;
    for (const SectionKey& key : keys) y.push_back(ToFields(key.section)[static_cast<size_t>(f)]);
    const std::vector<double> m = MonotoneSlopes(x, y);
    out[static_cast<size_t>(f)] = h00 * y[i] + h10 * h * m[i] + h01 * y[i + 1] + h11 * h * m[i + 1];
  }
  Section s = FromFields(out);
  // Monotone interpolation keeps every field between its neighbours, so the
  // flat part stays below the half-width; guard rounding anyway.
  s.front.w = std::min(s.front.w, 0.95 * s.a);
  s.back.w = std::min(s.back.w, 0.95 * s.a);
  return s;
}

BodyLayout MakeLayout(const ParametricBodyOptions& options) {
  BodyLayout L;
  L.options = SeededOptions(options);
  L.options.Check();
  const ParametricBodyOptions& o = L.options;
  const double H = o.stature_mm;
  L.z_crotch = o.crotch_height_mm;
  L.z_shoulder = 0.818 * H;
  L.z_back_neck = L.z_shoulder + 0.035 * H;
  L.z_jugulare = L.z_shoulder + 0.01 * H;
  L.z_chin = 0.870 * H;
  L.z_dome = L.z_chin + 0.62 * (H - L.z_chin);
  const double T = L.z_shoulder - L.z_crotch;
  L.z_hip = L.z_crotch + 0.125 * T;
  L.z_middle_hip = L.z_crotch + 0.29 * T;
  L.z_waist = L.z_crotch + 0.455 * T;
  L.z_under_bust = L.z_crotch + 0.62 * T;
  L.z_armpit = L.z_shoulder - 0.078 * H;
  L.z_bust = std::min(L.z_crotch + 0.73 * T, L.z_armpit - 0.012 * H);
  const double Zc = L.z_crotch;
  L.z_thigh = Zc - 0.025 * H;
  L.z_knee = 0.62 * Zc;
  L.z_calf = 0.43 * Zc;
  L.z_ankle = 0.14 * Zc;
  L.z_malleolus_inside = 0.105 * Zc;
  L.z_malleolus_outside = 0.088 * Zc;
  AddTorsoKeys(&L);
  AddLegKeys(&L);
  AddArmKeys(&L);
  for (const auto* keys : {&L.torso, &L.leg, &L.arm}) {
    for (size_t i = 0; i + 1 < keys->size(); ++i) {
      BESPOKE_CHECK((*keys)[i].at < (*keys)[i + 1].at,
                    "parametric body: key sections out of order");
    }
    for (const SectionKey& key : *keys) key.section.CheckValid();
  }
  return L;
}

}  // namespace bespoke
