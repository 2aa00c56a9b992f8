#include "resize/io/pattern_json.h"

#include <cmath>

#include "resize/io/measurements_io.h"
#include "resize/pattern/edit.h"
#include "resize/pattern/measurements.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

using nlohmann::json;

json Point(const Eigen::Vector2d& p) { return json::array({p.x(), p.y()}); }

json PolylineJson(const Outline& o) {
  json a = json::array();
  for (Eigen::Index i = 0; i < o.rows(); ++i) a.push_back(json::array({o(i, 0), o(i, 1)}));
  return a;
}

Eigen::Vector2d ParsePoint(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    throw InputError(where + ": expected a point [x, y]");
  Eigen::Vector2d p(j[0].get<double>(), j[1].get<double>());
  if (!p.allFinite()) throw InputError(where + ": point is not finite");
  return p;
}

Outline ParsePolyline(const json& j, const std::string& where) {
  if (!j.is_array()) throw InputError(where + ": expected an array of points");
  Outline o(static_cast<Eigen::Index>(j.size()), 2);
  for (size_t i = 0; i < j.size(); ++i) o.row(i) = ParsePoint(j[i], where).transpose();
  return o;
}

template <typename T>
T Get(const json& j, const char* key, const T& fallback, const std::string& where) {
  if (!j.contains(key)) return fallback;
  try {
    return j.at(key).get<T>();
  } catch (const json::exception&) {
    throw InputError(where + ": field \"" + key + "\" has the wrong type");
  }
}

template <typename T>
T Require(const json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key))
    throw InputError(where + ": missing field \"" + std::string(key) + "\"");
  return Get<T>(j, key, T{}, where);
}

int NearestVertex(const Outline& o, const Eigen::Vector2d& p) {
  Eigen::Index best = 0;
  (o.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return static_cast<int>(best);
}

// An outline vertex given as an index, the name of an outline landmark, or a
// point [x, y] (the nearest outline vertex).
int VertexRef(const json& j, const Piece& piece, const std::string& where) {
  if (j.is_number_integer()) return j.get<int>();
  if (j.is_string()) {
    const int l = piece.FindLandmark(j.get<std::string>());
    if (l < 0 || piece.landmarks[l].vertex < 0)
      throw InputError(where + ": '" + j.get<std::string>() + "' is not an outline landmark");
    return piece.landmarks[l].vertex;
  }
  if (j.is_array()) return NearestVertex(piece.outline, ParsePoint(j, where));
  throw InputError(where + ": a vertex is an index, an outline landmark name or a point [x, y]");
}

std::vector<StraightRun> ParseRuns(const json& list, bool fold, const Piece& piece,
                                   const std::string& where) {
  std::vector<StraightRun> runs;
  if (!list.is_array()) throw InputError(where + ": expected a list of [from, to] runs");
  for (const json& r : list) {
    if (!r.is_array() || r.size() != 2) throw InputError(where + ": a run is [from, to]");
    runs.push_back({VertexRef(r[0], piece, where), VertexRef(r[1], piece, where), fold});
  }
  return runs;
}

// Straight runs, folds, right angles, level lines and darts of a piece.
void ParseStructure(const json& j, const std::string& where, Piece* piece) {
  for (const char* key : {"straight", "folds"})
    if (j.contains(key))
      for (const StraightRun& r :
           ParseRuns(j[key], std::string(key) == "folds", *piece, where + ": " + key))
        piece->straight.push_back(r);
  if (j.contains("not_straight"))
    piece->not_straight = ParseRuns(j["not_straight"], false, *piece, where + ": not_straight");
  for (const json& v : j.value("right_angles", json::array()))
    piece->right_angles.push_back(VertexRef(v, *piece, where + ": right_angles"));
  for (const json& l : j.value("level_lines", json::array())) {
    LevelLine line;
    line.name = Require<std::string>(l, "name", where + ": level line");
    line.from = Require<std::string>(l, "from", where + ": level line");
    line.to = Require<std::string>(l, "to", where + ": level line");
    piece->level_lines.push_back(line);
  }
  for (const json& d : j.value("darts", json::array())) {
    const std::string dw = where + ": dart";
    const json legs = Require<json>(d, "legs", dw);
    if (!legs.is_array() || legs.size() != 2) throw InputError(dw + ": \"legs\" is [a, b]");
    piece->darts.push_back({VertexRef(Require<json>(d, "apex", dw), *piece, dw),
                            VertexRef(legs[0], *piece, dw), VertexRef(legs[1], *piece, dw)});
  }
}

void ParsePieceExtras(const json& j, const std::string& where, Piece* piece) {
  if (j.contains("critical")) piece->critical = Get<std::vector<int>>(j, "critical", {}, where);
  if (j.contains("notches")) piece->notches = Get<std::vector<int>>(j, "notches", {}, where);
  for (const json& l : j.value("landmarks", json::array())) {
    PieceLandmark landmark;
    landmark.name = Require<std::string>(l, "name", where + ": landmark");
    const std::string lw = where + ": landmark '" + landmark.name + "'";
    landmark.datum = Get<std::string>(l, "datum", "", lw);
    if (l.contains("vertex")) {
      landmark.vertex = Get<int>(l, "vertex", -1, lw);
    } else if (l.contains("near")) {
      landmark.vertex = NearestVertex(piece->outline, ParsePoint(l["near"], lw));
    } else if (l.contains("position")) {
      landmark.position = ParsePoint(l["position"], lw);
    } else {
      throw InputError(lw + ": needs \"vertex\", \"near\" or \"position\"");
    }
    const int existing = piece->FindLandmark(landmark.name);
    if (existing >= 0)
      piece->landmarks[existing] = landmark;
    else
      piece->landmarks.push_back(landmark);
  }
  if (j.contains("grain")) {
    piece->has_grain = true;
    piece->grain_start = ParsePoint(Require<json>(j["grain"], "start", where), where + ": grain");
    piece->grain_end = ParsePoint(Require<json>(j["grain"], "end", where), where + ": grain");
  }
  for (const json& line : j.value("internal_lines", json::array()))
    piece->internal_lines.push_back(ParsePolyline(line, where + ": internal line"));
  piece->cut_count = Get<int>(j, "cut_count", piece->cut_count, where);
  piece->mirrored = Get<bool>(j, "mirrored", piece->mirrored, where);
  piece->on_fold = Get<bool>(j, "on_fold", piece->on_fold, where);
  ParseStructure(j, where, piece);
}

// A seam end: a vertex index or the name of a landmark on the outline.
int SeamEnd(const json& j, const Pattern& pattern, const std::string& piece,
            const std::string& where) {
  if (j.is_number_integer()) return j.get<int>();
  if (j.is_string()) {
    const int p = pattern.FindPiece(piece);
    if (p < 0) throw InputError(where + ": unknown piece '" + piece + "'");
    const int l = pattern.pieces[p].FindLandmark(j.get<std::string>());
    if (l < 0 || pattern.pieces[p].landmarks[l].vertex < 0)
      throw InputError(where + ": '" + j.get<std::string>() + "' is not an outline landmark of '" +
                       piece + "'");
    return pattern.pieces[p].landmarks[l].vertex;
  }
  throw InputError(where + ": seam ends are vertex indices or landmark names");
}

SeamSide ParseSide(const json& j, const Pattern& pattern, const std::string& where) {
  SeamSide side;
  side.piece = Require<std::string>(j, "piece", where);
  side.from = SeamEnd(Require<json>(j, "from", where), pattern, side.piece, where);
  side.to = SeamEnd(Require<json>(j, "to", where), pattern, side.piece, where);
  const std::string direction = Get<std::string>(j, "direction", "forward", where);
  if (direction != "forward" && direction != "backward")
    throw InputError(where + ": direction must be \"forward\" or \"backward\"");
  side.forward = direction == "forward";
  return side;
}

// With `keep_by_default`, a binding that gives no ease keeps the base
// pattern's own (MeasurementBinding::keep_ease "mm").
void ParseSeamsAndBindings(const json& j, const std::string& what, bool keep_by_default,
                           Pattern* pattern) {
  for (const json& s : j.value("seams", json::array())) {
    Seam seam;
    seam.name = Require<std::string>(s, "name", what + ": seam");
    const std::string where = what + ": seam '" + seam.name + "'";
    seam.a = ParseSide(Require<json>(s, "a", where), *pattern, where);
    seam.b = ParseSide(Require<json>(s, "b", where), *pattern, where);
    seam.ease_mm = Get<double>(s, "ease_mm", 0.0, where);
    const std::string ease = Get<std::string>(s, "ease", "", where);
    if (!ease.empty() && ease != "keep") throw InputError(where + ": \"ease\" is \"keep\"");
    if (ease == "keep") seam.ease_mm = std::nan("");  // the base's own, after validation
    pattern->seams.push_back(seam);
  }
  for (const json& b : j.value("bindings", json::array())) {
    MeasurementBinding binding;
    binding.id = Require<std::string>(b, "id", what + ": binding");
    const std::string where = what + ": binding '" + binding.id + "'";
    binding.fixed = Get<bool>(b, "fixed", false, where);
    binding.follows = Get<std::string>(b, "follows", "", where);
    if (binding.fixed && !binding.follows.empty())
      throw InputError(where + ": a binding is \"fixed\" or \"follows\" another, not both");
    binding.measurement = binding.fixed || !binding.follows.empty()
                              ? ""
                              : Require<std::string>(b, "measurement", where);
    binding.ease_mm = Get<double>(b, "ease_mm", 0.0, where);
    binding.ease_percent = Get<double>(b, "ease_percent", 0.0, where);
    const std::string ease = Get<std::string>(b, "ease", "", where);
    if (!ease.empty() && ease != "keep" && ease != "keep_percent")
      throw InputError(where + ": \"ease\" is \"keep\" or \"keep_percent\"");
    if (!ease.empty() && (b.contains("ease_mm") || b.contains("ease_percent")))
      throw InputError(where + ": give \"ease\" or an ease value, not both");
    if (ease == "keep_percent") binding.keep_ease = "percent";
    if (!binding.fixed && binding.follows.empty() &&
        (ease == "keep" || (ease.empty() && !b.contains("ease_mm") && !b.contains("ease_percent") &&
                            keep_by_default)))
      binding.keep_ease = "mm";
    for (const json& t : Require<json>(b, "terms", where)) {
      BindingTerm term;
      term.piece = Require<std::string>(t, "piece", where);
      term.from = Require<std::string>(t, "from", where);
      term.to = Require<std::string>(t, "to", where);
      const std::string path = Get<std::string>(t, "path", "straight", where);
      if (path != "straight" && path != "outline")
        throw InputError(where + ": path must be \"straight\" or \"outline\"");
      term.path = path == "outline" ? BindingTerm::Path::kOutline : BindingTerm::Path::kStraight;
      term.multiplicity = Get<double>(t, "multiplicity", 1.0, where);
      binding.terms.push_back(term);
    }
    binding.fixed_mm = binding.fixed ? Get<double>(b, "value_mm", std::nan(""), where) : 0.0;
    pattern->bindings.push_back(binding);
  }
}

json SideJson(const SeamSide& s) {
  return {{"piece", s.piece},
          {"from", s.from},
          {"to", s.to},
          {"direction", s.forward ? "forward" : "backward"}};
}

// "base_measurements": a file (.vit or a measurement document; relative to
// `folder`) or an object {name: mm}.
void ParseBaseMeasurements(const json& j, const std::filesystem::path& folder,
                           const std::string& what, Pattern* pattern) {
  if (!j.contains("base_measurements")) return;
  const json& b = j["base_measurements"];
  if (b.is_string()) {
    std::filesystem::path file = b.get<std::string>();
    if (file.is_relative()) file = folder / file;
    const MeasurementSet set = LoadMeasurements(file);
    pattern->base_body.insert(set.begin(), set.end());
  } else if (b.is_object()) {
    for (const auto& [name, value] : b.items()) {
      if (!value.is_number() || !(value.get<double>() > 0))
        throw InputError(what + ": base measurement '" + name + "' must be a positive number (mm)");
      pattern->base_body[name] = value.get<double>();
    }
  } else {
    throw InputError(what + ": \"base_measurements\" is a file name or an object {name: mm}");
  }
}

// After validation: fixed bindings without a value keep the pattern's own,
// and bindings keeping the base's ease get it when the base body is known.
void FinishBindings(const std::string& what, Pattern* pattern) {
  for (MeasurementBinding& b : pattern->bindings)
    if (b.fixed && !std::isfinite(b.fixed_mm)) b.fixed_mm = BindingValue(*pattern, b);
  for (Seam& s : pattern->seams)
    if (!std::isfinite(s.ease_mm))
      s.ease_mm = SeamLength(pattern->pieces[pattern->FindPiece(s.a.piece)], s.a) -
                  SeamLength(pattern->pieces[pattern->FindPiece(s.b.piece)], s.b);
  if (!pattern->base_body.empty()) ResolveKeptEase(what, pattern);
}

}  // namespace

json PatternToJson(const Pattern& pattern) {
  json pieces = json::array();
  for (const Piece& p : pattern.pieces) {
    json landmarks = json::array();
    for (const PieceLandmark& l : p.landmarks) {
      json lj = {{"name", l.name}};
      if (!l.datum.empty()) lj["datum"] = l.datum;
      if (l.vertex >= 0)
        lj["vertex"] = l.vertex;
      else
        lj["position"] = Point(l.position);
      landmarks.push_back(lj);
    }
    json pj = {{"name", p.name},         {"outline", PolylineJson(p.outline)},
               {"critical", p.critical}, {"landmarks", landmarks},
               {"notches", p.notches},   {"cut_count", p.cut_count},
               {"mirrored", p.mirrored}, {"on_fold", p.on_fold}};
    if (p.has_grain) pj["grain"] = {{"start", Point(p.grain_start)}, {"end", Point(p.grain_end)}};
    json lines = json::array();
    for (const Outline& line : p.internal_lines) lines.push_back(PolylineJson(line));
    pj["internal_lines"] = lines;
    json straight = json::array(), folds = json::array(), levels = json::array(),
         darts = json::array();
    for (const StraightRun& r : p.straight) (r.fold ? folds : straight).push_back({r.from, r.to});
    for (const LevelLine& l : p.level_lines)
      levels.push_back({{"name", l.name}, {"from", l.from}, {"to", l.to}});
    for (const Dart& d : p.darts) darts.push_back({{"apex", d.apex}, {"legs", {d.leg_a, d.leg_b}}});
    pj["straight"] = straight;
    pj["folds"] = folds;
    pj["right_angles"] = p.right_angles;
    pj["level_lines"] = levels;
    pj["darts"] = darts;
    pieces.push_back(pj);
  }
  json seams = json::array();
  for (const Seam& s : pattern.seams)
    seams.push_back(
        {{"name", s.name}, {"a", SideJson(s.a)}, {"b", SideJson(s.b)}, {"ease_mm", s.ease_mm}});
  json bindings = json::array();
  for (const MeasurementBinding& b : pattern.bindings) {
    json terms = json::array();
    for (const BindingTerm& t : b.terms)
      terms.push_back({{"piece", t.piece},
                       {"from", t.from},
                       {"to", t.to},
                       {"path", t.path == BindingTerm::Path::kOutline ? "outline" : "straight"},
                       {"multiplicity", t.multiplicity}});
    json bj = {{"id", b.id}, {"terms", terms}};
    if (b.fixed) {
      bj["fixed"] = true;
      bj["value_mm"] = b.fixed_mm;
    } else if (!b.follows.empty()) {
      bj["follows"] = b.follows;
    } else {
      bj["measurement"] = b.measurement;
      bj["ease_mm"] = b.ease_mm;
      if (b.ease_percent != 0) bj["ease_percent"] = b.ease_percent;
      if (!b.keep_ease.empty()) {
        bj.erase("ease_mm");
        bj["ease"] = b.keep_ease == "percent" ? "keep_percent" : "keep";
      }
    }
    bindings.push_back(bj);
  }
  json document = {
      {"format", "bespoke-pattern"}, {"version", 1},     {"units", "mm"},  {"name", pattern.name},
      {"source", pattern.source},    {"pieces", pieces}, {"seams", seams}, {"bindings", bindings}};
  if (!pattern.base_body.empty()) document["base_measurements"] = pattern.base_body;
  if (!pattern.notes.empty()) document["import_notes"] = pattern.notes;
  return document;
}

Pattern PatternFromJson(const json& document, const std::string& what) {
  if (!document.is_object()) throw InputError(what + ": a pattern is a JSON object");
  if (document.value("format", "") != "bespoke-pattern")
    throw InputError(what + ": not a Bespoke pattern (\"format\" must be \"bespoke-pattern\")");
  if (document.value("units", "mm") != "mm") throw InputError(what + ": \"units\" must be \"mm\"");
  Pattern pattern;
  pattern.name = Get<std::string>(document, "name", "", what);
  pattern.source = Get<std::string>(document, "source", what, what);
  for (const json& pj : Require<json>(document, "pieces", what)) {
    Piece piece;
    piece.name = Require<std::string>(pj, "name", what + ": piece");
    const std::string where = what + ": piece '" + piece.name + "'";
    piece.outline = ParsePolyline(Require<json>(pj, "outline", where), where + ": outline");
    ParsePieceExtras(pj, where, &piece);
    pattern.pieces.push_back(std::move(piece));
  }
  ParseBaseMeasurements(document, std::filesystem::path(what).parent_path(), what, &pattern);
  ParseSeamsAndBindings(document, what, !pattern.base_body.empty(), &pattern);
  MakeCounterClockwise(&pattern);
  ValidatePattern(pattern, what);
  FinishBindings(what, &pattern);
  return pattern;
}

Pattern ReadPatternJson(const std::filesystem::path& file) {
  return PatternFromJson(ReadJsonFile(file), file.string());
}

void WritePatternJson(const Pattern& pattern, const std::filesystem::path& file) {
  WriteJsonFile(file, PatternToJson(pattern));
}

void ApplySidecar(const json& sidecar, const std::string& what, Pattern* pattern) {
  if (!sidecar.is_object()) throw InputError(what + ": a sidecar is a JSON object");
  if (sidecar.contains("name")) pattern->name = Get<std::string>(sidecar, "name", "", what);
  for (const json& pj : sidecar.value("pieces", json::array())) {
    const std::string name = Require<std::string>(pj, "name", what + ": piece");
    const int p = pattern->FindPiece(name);
    if (p < 0) {
      std::string known;
      for (const Piece& piece : pattern->pieces)
        known += (known.empty() ? "'" : ", '") + piece.name + "'";
      throw InputError(what + ": sidecar names unknown piece '" + name +
                       "' (the pattern's pieces: " + known + ")");
    }
    ParsePieceExtras(pj, what + ": piece '" + name + "'", &pattern->pieces[p]);
  }
  ParseBaseMeasurements(sidecar, std::filesystem::path(what).parent_path(), what, pattern);
  ParseSeamsAndBindings(sidecar, what, !pattern->base_body.empty(), pattern);
  ValidatePattern(*pattern, what, false);
  LandmarksOntoOutline(pattern);
  EqualizeSeamCounts(pattern);
  if (sidecar.value("infer_structure", true)) InferStructure(StructureOptions{}, pattern);
  AddStructureCriticalPoints(pattern);
  ValidatePattern(*pattern, what);
  FinishBindings(what, pattern);
}

}  // namespace bespoke
