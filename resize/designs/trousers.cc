// Trousers after the classic trouser block of W. Aldrich, "Metric Pattern
// Cutting for Menswear" (chapter "Classic and casual trousers"): crotch line
// at the body rise + 1 cm below the waist, seat line a quarter of the rise
// above it, knee line 5 cm above half way from crotch to hem, quarter-seat
// widths with ease, front and back fork extensions, a raised (2 cm) and
// sloped centre back, creased legs of a style width. The figures are the
// book's structure with values set for the standard size; pleats and darts
// are left out (the waist is shaped at the side seam), see docs/resize.md.
//
// Body measurements used: waist_girth, hip_girth (seat), inside_leg,
// waist_height (body rise = waist_height - inside_leg, bound as the derived
// measurement body_rise, resize/pattern/measurements.h).
#include <cmath>

#include "resize/designs/designs.h"
#include "resize/designs/piece_builder.h"
#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

using V = Eigen::Vector2d;

constexpr double kFrontHem = 210, kBackHem = 250;  // style: hem widths (mm)
constexpr double kKneeExtra = 20;                  // knee = hem + 2 cm
constexpr double kBandDepth = 40, kOverlap = 40;   // waistband (mm)
constexpr int kHipSamples = 5, kCrotchSamples = 7;

struct TrouserLines {
  double waist, seat, rise, leg;
  double y_seat, y_crotch, y_knee, y_hem;
};

TrouserLines Lines(double waist, double seat, double inside_leg, double waist_height) {
  TrouserLines t;
  t.waist = waist;
  t.seat = seat;
  t.rise = waist_height - inside_leg;
  t.leg = inside_leg;
  t.y_crotch = -(t.rise + 10);                 // 0-1 body rise + 1 cm
  t.y_seat = t.y_crotch + (t.rise + 10) / 4;   // seat line: quarter of 0-1 up
  t.y_hem = t.y_crotch - (inside_leg - 30);    // hem 3 cm above the floor
  t.y_knee = (t.y_crotch + t.y_hem) / 2 + 50;  // knee: half way + 5 cm
  return t;
}

PieceBuilder DraftFront(const TrouserLines& t) {
  // Side seam on the left (x = 0 at the seat line), centre front on the right.
  const double seat_x = t.seat / 4 + 5;            // quarter seat + ease
  const double fork_x = seat_x + t.seat / 20 + 5;  // front fork extension
  const double crease = fork_x / 2;
  const V cf_waist(seat_x - 10, 0), side_waist(cf_waist.x() - (t.waist / 4 + 10), 0);
  const V side_seat(0, t.y_seat), side_crotch(2, t.y_crotch);
  const V knee_out(crease - (kFrontHem + kKneeExtra) / 2, t.y_knee);
  const V hem_out(crease - kFrontHem / 2, t.y_hem), hem_in(crease + kFrontHem / 2, t.y_hem);
  const V knee_in(crease + (kFrontHem + kKneeExtra) / 2, t.y_knee);
  const V fork(fork_x, t.y_crotch), cf_seat(seat_x, t.y_seat);
  PieceBuilder f("front");
  f.Add(side_waist, "side_waist", "waist_side", true);
  f.AddCurve(
      SmoothCurve({side_waist, V(side_waist.x() * 0.35, t.y_seat * 0.5), side_seat}, kHipSamples));
  f.Add(side_seat, "side_seat", "hip_side", true);
  f.Add(side_crotch, "side_crotch", "", true);
  f.Add(knee_out, "knee_out", "knee_side", true);
  f.Add(hem_out, "hem_out", "", true);
  f.Add(hem_in, "hem_in", "", true);
  f.Add(knee_in, "knee_in", "", true);
  f.AddCurve(SmoothCurve({knee_in, (knee_in + fork) / 2 + V(-4, 0), fork}, 4));
  f.Add(fork, "fork", "crotch_point", true);
  const V corner(seat_x, t.y_crotch);
  f.AddCurve(SmoothCurve({fork, Bisector(corner, fork, cf_seat, 25), cf_seat}, kCrotchSamples));
  f.Add(cf_seat, "cf_seat", "", true);
  f.Add(cf_waist, "cf_waist", "front_waist_point", true);
  // Construction point 0 of the draft: the side construction line (x = 0,
  // through the seat and crotch lines) meets the waist line. Not on the
  // outline (the waist is shaped in from it); bindings measure the crotch
  // depth from it, parallel to the grain as the draft sets it out.
  f.AddInside("side_line_waist", V(0, 0));
  f.Notch(f.Index("side_seat"));
  f.Notch(f.Index("knee_in"));
  f.Grain(V(crease, t.y_seat - 20), V(crease, t.y_hem + 80));
  f.Cut(2, true);
  return f;
}

PieceBuilder DraftBack(const TrouserLines& t) {
  // Centre back on the left (x = 0 at the seat line), side seam on the right.
  const double seat_x = t.seat / 4 + 20;      // quarter seat + ease
  const double fork_x = -(t.seat / 10 + 10);  // back fork extension
  const double crease = (fork_x + seat_x) / 2;
  const V cb_waist(40, 20);  // CB raised 2 cm, sloped 4 cm
  const double w = t.waist / 4 + 10;
  const V side_waist(cb_waist.x() + std::sqrt(w * w - 20.0 * 20.0), 0);
  const V cb_seat(0, t.y_seat), fork(fork_x, t.y_crotch - 10);
  const V knee_in(crease - (kBackHem + kKneeExtra) / 2, t.y_knee);
  const V hem_in(crease - kBackHem / 2, t.y_hem), hem_out(crease + kBackHem / 2, t.y_hem);
  const V knee_out(crease + (kBackHem + kKneeExtra) / 2, t.y_knee);
  const V side_crotch(seat_x - 5, t.y_crotch), side_seat(seat_x, t.y_seat);
  PieceBuilder b("back");
  b.Add(cb_waist, "cb_waist", "back_waist_point", true);
  b.Add(cb_seat, "cb_seat", "", true);
  const V corner(0, t.y_crotch - 10);
  b.AddCurve(SmoothCurve({cb_seat, Bisector(corner, cb_seat, fork, 35), fork}, kCrotchSamples));
  b.Add(fork, "fork", "crotch_point", true);
  b.AddCurve(SmoothCurve({fork, (fork + knee_in) / 2 + V(6, 0), knee_in}, 4));
  b.Add(knee_in, "knee_in", "", true);
  b.Add(hem_in, "hem_in", "", true);
  b.Add(hem_out, "hem_out", "", true);
  b.Add(knee_out, "knee_out", "knee_side", true);
  b.Add(side_crotch, "side_crotch", "", true);
  b.Add(side_seat, "side_seat", "hip_side", true);
  b.AddCurve(SmoothCurve(
      {side_seat, V(side_seat.x() + (side_waist.x() - side_seat.x()) * 0.35 + 4, t.y_seat * 0.5),
       side_waist},
      kHipSamples));
  b.Add(side_waist, "side_waist", "waist_side", true);
  b.AddInside("side_line_waist", V(seat_x, 0));  // as on the front
  b.Notch(b.Index("side_seat"));
  b.Notch(b.Index("knee_in"));
  b.Grain(V(crease, t.y_seat - 20), V(crease, t.y_hem + 80));
  b.Cut(2, true);
  return b;
}

PieceBuilder DraftBand(double back_waist, double front_waist) {
  // Half waistband (cut 2, CB seam): back waist, front waist, then the overlap.
  PieceBuilder w("waistband");
  w.Add(V(0, 0), "cb", "back_waist_point", true);
  w.Add(V(back_waist, 0), "side", "waist_side", true);
  w.Add(V(back_waist + front_waist, 0), "cf", "front_waist_point", true);
  w.Add(V(back_waist + front_waist + kOverlap, 0), "overlap_end", "", true);
  w.Add(V(back_waist + front_waist + kOverlap, kBandDepth), "top_end", "", true);
  w.Add(V(0, kBandDepth), "cb_top", "", true);
  w.Notch(1);
  w.Notch(2);
  w.Grain(V(20, kBandDepth / 2), V(back_waist, kBandDepth / 2));
  w.Cut(2, true);
  return w;
}

}  // namespace

Pattern DraftTrousers(const MeasurementSet& m) {
  const std::string d = "trousers";
  const TrouserLines t = Lines(Need(m, "waist_girth", d), Need(m, "hip_girth", d),
                               Need(m, "inside_leg", d), Need(m, "waist_height", d));
  PieceBuilder front = DraftFront(t), back = DraftBack(t);
  Pattern p;
  p.name = "trousers";
  p.source = "built-in design: after Aldrich classic trouser block";
  p.pieces.push_back(front.Build());
  p.pieces.push_back(back.Build());
  const double front_waist = OutlineDistance(p.pieces[0].outline, front.Index("cf_waist"), 0);
  const double back_waist = OutlineDistance(p.pieces[1].outline, back.Index("side_waist"), 0);
  PieceBuilder band = DraftBand(back_waist, front_waist);
  p.pieces.push_back(band.Build());

  auto seam = [&](const char* name, SeamSide a, SeamSide b) {
    Seam s;
    s.name = name;
    s.a = a;
    s.b = b;
    p.seams.push_back(s);
  };
  seam("side", Side(front, "front", "side_waist", "hem_out", true),
       Side(back, "back", "side_waist", "hem_out", false));
  seam("inseam", Side(front, "front", "fork", "hem_in", false),
       Side(back, "back", "fork", "hem_in", true));
  seam("band_back", Side(band, "waistband", "cb", "side", true),
       Side(back, "back", "cb_waist", "side_waist", false));
  seam("band_front", Side(band, "waistband", "side", "cf", true),
       Side(front, "front", "side_waist", "cf_waist", false));

  using Path = BindingTerm::Path;
  auto term = [](const char* piece, const char* from, const char* to, Path path, double k) {
    BindingTerm x;
    x.piece = piece;
    x.from = from;
    x.to = to;
    x.path = path;
    x.multiplicity = k;
    return x;
  };
  auto bind = [&](const char* id, const char* measurement, std::vector<BindingTerm> terms) {
    MeasurementBinding b;
    b.id = id;
    b.measurement = measurement;
    b.terms = std::move(terms);
    p.bindings.push_back(b);
  };
  const Path S = Path::kStraight, O = Path::kOutline;
  // Totals, then the draft's own rules that split them or derive a
  // dimension from a measurement (each a quarter-girth or rise rule of the
  // draft above), so the fit distributes a change as the drafting system does
  // instead of as proportional grading or the shape objective would.
  bind("waist", "waist_girth",
       {term("front", "cf_waist", "side_waist", O, 2),
        term("back", "side_waist", "cb_waist", O, 2)});
  bind("front_waist", "waist_girth", {term("front", "cf_waist", "side_waist", O, 4)});
  bind("seat", "hip_girth",
       {term("front", "side_seat", "cf_seat", S, 2), term("back", "cb_seat", "side_seat", S, 2)});
  bind("front_seat", "hip_girth", {term("front", "side_seat", "cf_seat", S, 4)});
  bind("inside_leg", "inside_leg", {term("front", "hem_in", "fork", O, 1)});
  bind("side_length", "waist_height", {term("front", "side_waist", "hem_out", S, 1)});
  // The crotch depth (0-1 = rise + 1 cm) on the side construction line of
  // the front and of the back (2 and 5 mm off the vertical), and at the
  // centre front (waist to seat line plus seat to crotch line, 10 and 2 mm
  // off): draft and bindings agree within 0.2 mm for rises 40 mm shorter to
  // 60 mm longer than the standard. Without them the fit can meet waist,
  // seat, inside leg and side length with the crotch line too high, or tilt
  // the seat line so that only the centre front follows the rise.
  bind("rise", "body_rise", {term("front", "side_line_waist", "side_crotch", S, 1)});
  bind("back_rise", "body_rise", {term("back", "side_line_waist", "side_crotch", S, 1)});
  bind("rise_cf", "body_rise",
       {term("front", "cf_waist", "cf_seat", S, 1),
        term("front", "side_seat", "side_crotch", S, 1)});
  // The seat line a quarter of 0-1 above the crotch line, front and back
  // (2 and 5 mm across).
  bind("front_seat_line", "body_rise", {term("front", "side_seat", "side_crotch", S, 4)});
  bind("back_seat_line", "body_rise", {term("back", "side_crotch", "side_seat", S, 4)});
  // The hem widths are style widths of the draft, the same for every body:
  // fixed, so resizing keeps them instead of grading them.
  auto fix = [&](const char* id, const char* piece, const char* from, const char* to,
                 double width_mm) {
    MeasurementBinding b;
    b.id = id;
    b.fixed = true;
    b.fixed_mm = width_mm;
    b.terms = {term(piece, from, to, S, 1)};
    p.bindings.push_back(b);
  };
  fix("front_hem", "front", "hem_out", "hem_in", kFrontHem);
  fix("back_hem", "back", "hem_in", "hem_out", kBackHem);
  return p;
}

}  // namespace bespoke
