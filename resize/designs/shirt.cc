// The classic shirt block after W. Aldrich, "Metric Pattern Cutting for
// Menswear" (chapter "Classic and casual shirts"). Aldrich drafts in cm with y
// pointing down from the back neck point 0; here everything is mm with y up,
// so "down d" is y = -d. Point numbers in comments are Aldrich's.
//
// Body measurements used (catalogue names): chest_girth (chest), neck_girth
// (neck size), back_length (natural waist length), back_width (2 x half back),
// armhole_length (gives the scye depth: Aldrich's size charts have scye depth
// close to half the armhole girth, which we use because scye depth is not a
// catalogue measurement), waist_to_hip (shirt length = back_length +
// waist_to_hip + 150 mm, Aldrich's ~80 cm at the standard size), arm_length
// (sleeve), wrist_girth (cuff).
#include <cmath>

#include "resize/designs/designs.h"
#include "resize/designs/piece_builder.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using V = Eigen::Vector2d;

constexpr int kArmholeSamples = 13;  // vertices along each armhole / crown half
constexpr int kNeckSamples = 7;      // vertices along the back and the front neck
constexpr double kCuffDepth = 60;    // finished cuff depth (mm)
constexpr double kCuffEase = 60;     // cuff length = wrist + ease incl. overlap (mm)
constexpr double kPleats = 30;       // two 15 mm pleats at the sleeve hem (mm)
constexpr double kStand = 15;        // button stand, 21-27 (mm)
constexpr double kCollarDepth = 75;  // one-piece collar depth at CB (mm)

struct ShirtInput {
  double chest, neck, nwl, half_back, scye, shirt_length, arm, wrist;
};

// Pushes the midpoint of a-b sideways by `offset` (positive = to the left of a->b).
V Bulge(const V& a, const V& b, double t, double offset) {
  const V d = (b - a).normalized();
  return a + (b - a) * t + V(-d.y(), d.x()) * offset;
}

struct Body {
  PieceBuilder back{"back"}, front{"front"};
  double back_armhole = 0, front_armhole = 0, back_neck = 0, front_neck = 0;
};

Body DraftBody(const ShirtInput& in) {
  // Body section, Aldrich steps 0-36 (back and front drafted side by side).
  const V p0(0, 0);
  const double y1 = -(in.scye + 40);               // 0-1 scye depth + 4 cm
  const double y2 = -(in.nwl + 30);                // 0-2 natural waist length + 3 cm
  const double y3 = -(in.shirt_length + 80);       // 0-3 shirt length + 8 cm
  const double x4 = in.chest / 2 + 120;            // 1-4 half chest + 12 cm
  const V p8(in.neck / 5 - 5, 45);                 // 0-7 neck/5 - 0.5; 7-8 4.5 cm up
  const double y9 = -((in.scye + 40) / 5 + 20);    // 0-9 (0-1)/5 + 2 cm
  const double x10 = in.half_back + 40;            // 9-10 half back + 4 cm
  const V p13(x10 + 7.5, 0);                       // 12-13 0.75 cm
  const V p14(x10, y9 - 100), p15(x10 + 7.5, y9);  // 10-14 10 cm, 10-15 0.75 cm
  const V p16(x4 / 2 + 5, y1);                     // 1-16 (1-4)/2 + 0.5 cm
  const V p20(x4 - (in.neck / 5 - 10), -45);       // 5-19 4.5 cm; 19-20 neck/5 - 1
  const V p21(x4, -45 - (in.neck / 5 - 25));       // 19-21 neck/5 - 2.5
  const double y22 = y9 - 15;                      // 10-22 1.5 cm
  const double shoulder = (p13 - p8).norm() + 5;   // 20-23 = 8-13 + 0.5 cm
  const double dy = p20.y() - y22;
  const V p23(p20.x() - std::sqrt(std::max(shoulder * shoulder - dy * dy, 1.0)), y22);
  const V p25(in.chest / 3 + 45, y1 + 30);               // 1-24 chest/3 + 4.5; 24-25 3 cm
  const V p26 = Bulge(p23, p25, 0.5, -10);               // 23-26 half, curve in 1 cm
  const V p29(p16.x() - 20, y2), p30(p16.x() + 20, y2);  // 17-29, 17-30 2 cm
  const V p33(p16.x() - 10, y3 + 200), p32(p16.x() + 10, y3 + 200);  // 18-31 20 cm; 1 cm
  const V p35(p16.x() / 2, y3);                                      // 35 midway 3-18
  const V p36((x4 + p16.x()) / 2, y3 + 40);                          // 34 midway 6-18; 34-36 4 cm
  const V edge_hem(x4 + kStand, y3 + 40), edge_top(x4 + kStand, p21.y());

  Body body;
  // Back (cut 1 on the fold at CB), counter-clockwise from the back neck point.
  PieceBuilder& b = body.back;
  b.Add(p0, "cb_neck", "back_neck_point", true);
  b.Add(V(0, y9), "cb_yoke");
  b.Add(V(0, y1), "cb_chest");
  b.Add(V(0, y2), "cb_waist", "back_waist_point", true);
  b.Add(V(0, y3), "cb_hem", "", true);
  b.Add(p35, "back_hem_mid", "", true);
  b.AddCurve(SampleCubic(p35, V(p35.x() + 0.6 * (p33.x() - p35.x()), y3),
                         V(p33.x(), y3 + 0.5 * (p33.y() - y3)), p33, 6));
  b.Add(p33, "back_side_hem", "", true);
  b.Add(p29, "back_side_waist", "", true);
  b.Add(p16, "back_underarm", "armpit", true);
  const V back_corner(x10, y1);
  const std::vector<V> back_armhole =
      SmoothCurve({p16, Bisector(back_corner, p16, p14, 25), p14, p15, p13}, kArmholeSamples);
  b.AddCurve(back_armhole);
  b.Add(p13, "back_shoulder", "shoulder_point", true);
  b.Add(p8, "back_side_neck", "side_neck_point", true);
  b.AddCurve(SampleCubic(p8, V(p8.x(), p8.y() * 0.35), V(p8.x() * 0.55, 0), p0, kNeckSamples));
  b.MarkCritical(b.Index("back_underarm") + kArmholeSamples / 2);  // armhole turning point
  b.Notch(b.Index("back_underarm") + kArmholeSamples / 2);
  b.Notch(b.Index("cb_waist"));
  b.Grain(V(60, y1 + 40), V(60, y3 + 120));
  b.Cut(1, false, true);

  // Front (cut 2, mirrored), counter-clockwise from the underarm point.
  PieceBuilder& f = body.front;
  f.Add(p16, "front_underarm", "armpit", true);
  f.Add(p30, "front_side_waist", "", true);
  f.Add(p32, "front_side_hem", "", true);
  f.AddCurve(SampleCubic(p32, V(p32.x(), p36.y() + 0.35 * (p32.y() - p36.y())),
                         V(p32.x() + 0.5 * (p36.x() - p32.x()), p36.y()), p36, 6));
  f.Add(p36, "front_hem_mid", "", true);
  f.Add(edge_hem, "front_edge_hem", "", true);
  f.Add(V(edge_top.x(), y2), "front_edge_waist", "front_waist_point");
  f.Add(V(edge_top.x(), y1), "front_edge_chest");
  f.Add(V(edge_top.x(), 0.5 * (y1 + edge_top.y())));
  f.Add(edge_top, "front_edge_top", "", true);
  f.Add(p21, "cf_neck", "front_neck_point", true);
  f.AddCurve(SampleCubic(p21, V(p21.x() - 0.45 * (p21.x() - p20.x()), p21.y()),
                         V(p20.x(), p20.y() - 0.55 * (p20.y() - p21.y())), p20, kNeckSamples));
  f.Add(p20, "front_side_neck", "side_neck_point", true);
  f.Add(p23, "front_shoulder", "shoulder_point", true);
  const V front_corner(p25.x(), y1);
  const std::vector<V> front_armhole =
      SmoothCurve({p23, p26, p25, Bisector(front_corner, p25, p16, 20), p16}, kArmholeSamples);
  f.AddCurve(front_armhole);
  f.AddInside("cf_chest", V(x4, y1));
  f.MarkCritical(f.Index("front_shoulder") + kArmholeSamples / 2);
  f.Notch(f.Index("front_shoulder") + kArmholeSamples / 2);
  f.Grain(V(x4 - 80, y1 + 40), V(x4 - 80, y3 + 120));
  f.Cut(2, true);
  return body;
}

PieceBuilder DraftSleeve(const ShirtInput& in, double back_armhole, double front_armhole) {
  // Shirt sleeve in Aldrich's manner: crown height a quarter of the armhole
  // (0-1), crown diagonals from the crown top to the crown line (0-3 back,
  // 0-4 front) 5 mm shorter than each armhole half, the crown shaped 1.5 cm
  // out in its upper quarter and hollowed in its lower quarter; length 0-2 =
  // arm length + 3 cm - cuff depth; hem = cuff length + pleats.
  const double armhole = back_armhole + front_armhole;
  const double crown = armhole / 4;
  const double length = in.arm + 30 - kCuffDepth;
  const double db = back_armhole - 5, df = front_armhole - 5;
  const V top(0, 0);
  const V p3(-std::sqrt(std::max(db * db - crown * crown, 1.0)), -crown);
  const V p4(std::sqrt(std::max(df * df - crown * crown, 1.0)), -crown);
  const double hem_half = (in.wrist + kCuffEase + kPleats) / 2;
  const V p5(-hem_half, -length), p6(hem_half, -length), p2(0, -length);
  PieceBuilder s("sleeve");
  s.Add(top, "crown_top", "shoulder_point", true);
  s.AddCurve(SmoothCurve(
      {top, Bulge(top, p3, 0.25, 15), Bulge(top, p3, 0.5, 5), Bulge(top, p3, 0.78, -5), p3},
      kArmholeSamples));
  s.Add(p3, "back_underarm", "armpit", true);
  s.Add((p3 + p5) / 2, "back_elbow");
  s.Add(p5, "back_hem", "", true);
  s.Add(p2, "hem_mid", "wrist", true);
  s.Add(p6, "front_hem", "", true);
  s.Add((p4 + p6) / 2, "front_elbow");
  s.Add(p4, "front_underarm", "armpit", true);
  s.AddCurve(SmoothCurve(
      {p4, Bulge(p4, top, 0.22, -10), Bulge(p4, top, 0.5, 5), Bulge(p4, top, 0.75, 18), top},
      kArmholeSamples));
  s.MarkCritical(kArmholeSamples / 2);
  s.Notch(0);
  s.Grain(V(0, -crown - 40), V(0, -length + 60));
  s.Cut(2, true);
  return s;
}

PieceBuilder DraftCuff(const ShirtInput& in) {
  // A straight barrel cuff: wrist + 6 cm (ease and button overlap) by 6 cm.
  const double length = in.wrist + kCuffEase;
  PieceBuilder c("cuff");
  c.Add(V(0, 0), "seam_start", "", true);
  c.Add(V(length / 2, 0), "seam_mid");
  c.Add(V(length, 0), "seam_end", "", true);
  c.Add(V(length, kCuffDepth), "edge_end", "", true);
  c.Add(V(0, kCuffDepth), "edge_start", "", true);
  c.Grain(V(length * 0.2, kCuffDepth / 2), V(length * 0.8, kCuffDepth / 2));
  c.Cut(2, false);
  return c;
}

PieceBuilder DraftCollar(double back_neck, double front_neck) {
  // One-piece shirt collar, half on the CB fold: neck edge = back neck, then
  // front neck rising 1 cm to the centre front, then the 1.5 cm button stand;
  // 7.5 cm deep at CB, the point extended 1.5 cm past the stand end.
  const V cb(0, 0), shoulder(back_neck, 0);
  PieceBuilder c("collar");
  c.Add(cb, "cb_neck", "back_neck_point", true);
  c.AddLineTo(shoulder, kNeckSamples - 2);
  c.Add(shoulder, "shoulder_notch", "side_neck_point", true);
  const V cf(back_neck + front_neck, 10);
  c.AddCurve(SampleQuadratic(shoulder, V(back_neck + 0.6 * front_neck, 0), cf, kNeckSamples));
  c.Add(cf, "cf_neck", "front_neck_point", true);
  const V stand_end = cf + V(kStand, 2);
  c.Add(stand_end, "stand_end", "", true);
  c.Add(stand_end + V(kStand, kCollarDepth - 5), "collar_point", "", true);
  c.Add(V(0, kCollarDepth), "cb_top", "", true);
  c.Notch(c.Index("shoulder_notch"));
  c.Grain(V(20, kCollarDepth / 2), V(back_neck, kCollarDepth / 2));
  c.Cut(1, false, true);
  return c;
}

void AddShirtSeams(const std::vector<PieceBuilder>& b, Pattern* p) {
  const PieceBuilder &back = b[0], &front = b[1], &sleeve = b[2], &cuff = b[3], &collar = b[4];
  auto seam = [&](const std::string& name, SeamSide a, SeamSide s) {
    Seam x;
    x.name = name;
    x.a = a;
    x.b = s;
    p->seams.push_back(x);
  };
  seam("side", Side(back, "back", "back_underarm", "back_side_hem", false),
       Side(front, "front", "front_underarm", "front_side_hem", true));
  seam("shoulder", Side(back, "back", "back_shoulder", "back_side_neck", true),
       Side(front, "front", "front_shoulder", "front_side_neck", false));
  seam("back_armhole", Side(back, "back", "back_shoulder", "back_underarm", false),
       Side(sleeve, "sleeve", "crown_top", "back_underarm", true));
  seam("front_armhole", Side(front, "front", "front_shoulder", "front_underarm", true),
       Side(sleeve, "sleeve", "crown_top", "front_underarm", false));
  seam("underarm", Side(sleeve, "sleeve", "back_underarm", "back_hem", true),
       Side(sleeve, "sleeve", "front_underarm", "front_hem", false));
  seam("cuff", Side(sleeve, "sleeve", "back_hem", "front_hem", true),
       Side(cuff, "cuff", "seam_start", "seam_end", true));
  seam("collar_back", Side(back, "back", "cb_neck", "back_side_neck", false),
       Side(collar, "collar", "cb_neck", "shoulder_notch", true));
  seam("collar_front", Side(front, "front", "front_side_neck", "front_edge_top", false),
       Side(collar, "collar", "shoulder_notch", "stand_end", true));
}

void AddShirtBindings(Pattern* p) {
  using Path = BindingTerm::Path;
  auto term = [](const char* piece, const char* from, const char* to, Path path, double k) {
    BindingTerm t;
    t.piece = piece;
    t.from = from;
    t.to = to;
    t.path = path;
    t.multiplicity = k;
    return t;
  };
  auto bind = [&](const char* id, const char* measurement, std::vector<BindingTerm> terms) {
    MeasurementBinding b;
    b.id = id;
    b.measurement = measurement;
    b.terms = std::move(terms);
    p->bindings.push_back(b);
  };
  const Path S = Path::kStraight, O = Path::kOutline;
  bind("chest", "chest_girth",
       {term("back", "cb_chest", "back_underarm", S, 2),
        term("front", "front_underarm", "cf_chest", S, 2)});
  bind("neck", "neck_girth",
       {term("back", "back_side_neck", "cb_neck", O, 2),
        term("front", "cf_neck", "front_side_neck", O, 2)});
  bind("back_length", "back_length", {term("back", "cb_neck", "cb_waist", S, 1)});
  bind("back_width", "back_width", {term("back", "cb_yoke", "back_shoulder", S, 2)});
  bind("armhole", "armhole_length",
       {term("back", "back_underarm", "back_shoulder", O, 1),
        term("front", "front_shoulder", "front_underarm", O, 1)});
  bind("shirt_length", "waist_to_hip", {term("back", "cb_waist", "cb_hem", S, 1)});
  // The front's balance: Aldrich drafts front and back on the same scye,
  // waist and hem lines, so the front's neck-to-waist length follows the
  // natural waist length too (a tailor's "front balance"), measured down the
  // front edge (a straight vertical line, so the binding fixes the length).
  bind("front_balance", "back_length", {term("front", "front_edge_top", "front_edge_waist", S, 1)});
  bind("front_hem", "waist_to_hip", {term("front", "front_edge_hem", "front_edge_waist", S, 1)});
  bind("sleeve", "arm_length", {term("sleeve", "crown_top", "hem_mid", S, 1)});
  bind("cuff", "wrist_girth", {term("cuff", "seam_start", "seam_end", S, 1)});
}

}  // namespace

Pattern DraftShirt(const MeasurementSet& m) {
  const std::string d = "shirt";
  ShirtInput in;
  in.chest = Need(m, "chest_girth", d);
  in.neck = Need(m, "neck_girth", d);
  in.nwl = Need(m, "back_length", d);
  in.half_back = Need(m, "back_width", d) / 2;
  in.scye = Need(m, "armhole_length", d) / 2;
  in.shirt_length = in.nwl + Need(m, "waist_to_hip", d) + 150;
  in.arm = Need(m, "arm_length", d);
  in.wrist = Need(m, "wrist_girth", d);

  Body body = DraftBody(in);
  Pattern pattern;
  pattern.name = "shirt";
  pattern.source = "built-in design: Aldrich classic shirt block";
  std::vector<PieceBuilder> builders = {body.back, body.front};
  Piece back = body.back.Build(), front = body.front.Build();
  const double back_armhole = OutlineDistance(back.outline, body.back.Index("back_underarm"),
                                              body.back.Index("back_shoulder"));
  const double front_armhole =
      OutlineDistance(front.outline, body.front.Index("front_shoulder"), 0);
  const double back_neck = OutlineDistance(back.outline, body.back.Index("back_side_neck"), 0);
  const double front_neck = OutlineDistance(front.outline, body.front.Index("cf_neck"),
                                            body.front.Index("front_side_neck")) +
                            0;
  builders.push_back(DraftSleeve(in, back_armhole, front_armhole));
  builders.push_back(DraftCuff(in));
  builders.push_back(DraftCollar(back_neck, front_neck));
  for (PieceBuilder& b : builders) pattern.pieces.push_back(b.Build());
  AddShirtSeams(builders, &pattern);
  AddShirtBindings(&pattern);
  return pattern;
}

}  // namespace bespoke
