// DXF reader for AAMA/ASTM pattern files (R12 and 2000). See pattern_dxf.h.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "resize/io/pattern_dxf.h"
#include "resize/pattern/edit.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"
#include "scanners/core/text.h"

namespace bespoke {
namespace {

struct Pair {
  int code;
  std::string value;
  int line;
};

std::vector<Pair> Tokenise(const std::string& text, const std::string& what) {
  std::vector<Pair> pairs;
  std::istringstream in(text);
  std::string code, value;
  int line = 0;
  while (std::getline(in, code)) {
    ++line;
    if (!std::getline(in, value))
      throw InputError(what + ": line " + std::to_string(line) + ": group code without a value");
    ++line;
    try {
      size_t used = 0;
      const int c = std::stoi(StripBlanks(code), &used);
      if (used != StripBlanks(code).size()) throw std::invalid_argument("trailing");
      pairs.push_back({c, StripBlanks(value), line});
    } catch (const std::exception&) {
      throw InputError(what + ": line " + std::to_string(line - 1) + ": bad group code '" +
                       StripBlanks(code) + "'");
    }
  }
  return pairs;
}

double Number(const Pair& p, const std::string& what) {
  try {
    size_t used = 0;
    const double v = std::stod(p.value, &used);
    if (used != p.value.size() || !std::isfinite(v)) throw std::invalid_argument("bad");
    return v;
  } catch (const std::exception&) {
    throw InputError(what + ": line " + std::to_string(p.line) + ": bad number '" + p.value + "'");
  }
}

// One entity: its type and group pairs (for POLYLINE: the VERTEX points too).
struct Entity {
  std::string type, layer;
  std::vector<Pair> pairs;
  std::vector<Eigen::Vector2d> points;
  bool closed = false;
};

struct RawBlock {
  std::string name;
  std::vector<Entity> entities;
};

struct Insert {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  Eigen::Vector2d scale = Eigen::Vector2d::Ones();
  double angle_deg = 0;
};

double Get(const Entity& e, int code, double fallback, const std::string& what) {
  for (const Pair& p : e.pairs)
    if (p.code == code) return Number(p, what);
  return fallback;
}

std::string GetText(const Entity& e, int code) {
  for (const Pair& p : e.pairs)
    if (p.code == code) return p.value;
  return "";
}

// Splits the pair stream into entities (0-delimited), folding VERTEX/SEQEND
// into their POLYLINE and reading LWPOLYLINE point lists.
std::vector<Entity> Entities(const std::vector<Pair>& pairs, size_t begin, size_t end,
                             const std::string& what) {
  std::vector<Entity> entities;
  Entity* polyline = nullptr;
  for (size_t i = begin; i < end;) {
    Entity e;
    e.type = pairs[i].value;
    for (++i; i < end && pairs[i].code != 0; ++i) {
      if (pairs[i].code == 8) e.layer = pairs[i].value;
      e.pairs.push_back(pairs[i]);
    }
    if (e.type == "VERTEX" && polyline) {
      polyline->points.emplace_back(Get(e, 10, 0, what), Get(e, 20, 0, what));
      continue;
    }
    if (e.type == "SEQEND") {
      polyline = nullptr;
      continue;
    }
    if (e.type == "POLYLINE") e.closed = (static_cast<int>(Get(e, 70, 0, what)) & 1) != 0;
    if (e.type == "LWPOLYLINE") {
      e.closed = (static_cast<int>(Get(e, 70, 0, what)) & 1) != 0;
      double x = 0;
      for (const Pair& p : e.pairs) {
        if (p.code == 10) x = Number(p, what);
        if (p.code == 20) e.points.emplace_back(x, Number(p, what));
      }
    }
    entities.push_back(std::move(e));
    polyline = entities.back().type == "POLYLINE" ? &entities.back() : nullptr;
  }
  return entities;
}

Outline Clean(std::vector<Eigen::Vector2d> points) {
  std::vector<Eigen::Vector2d> kept;
  for (const Eigen::Vector2d& p : points)
    if (kept.empty() || (p - kept.back()).norm() > 1e-6) kept.push_back(p);
  while (kept.size() > 1 && (kept.front() - kept.back()).norm() <= 1e-6) kept.pop_back();
  Outline o(static_cast<Eigen::Index>(kept.size()), 2);
  for (size_t i = 0; i < kept.size(); ++i) o.row(i) = kept[i].transpose();
  return o;
}

// A notch farther than this along the sew line from the nearest vertex gets
// a vertex of its own (mm): half the 1 mm a notch may shift in a fit.
constexpr double kNotchVertexMm = 0.5;

// Puts a notch at the point of the sew line nearest to each of `points`
// (Valentina marks notches on the cut line): at the nearest vertex when it is
// within kNotchVertexMm, else at a vertex added there (the outline's shape
// is unchanged), so the notch keeps its place along its seam. Notes say
// where vertices were added.
void PlaceNotches(const std::vector<Eigen::Vector2d>& points, Piece* piece,
                  std::vector<std::string>* notes) {
  std::set<int> notches;
  int added = 0;
  for (const Eigen::Vector2d& q : points) {
    Outline& o = piece->outline;
    const int n = piece->num_vertices();
    int edge = 0;
    double best = std::numeric_limits<double>::infinity(), best_t = 0;
    for (int v = 0; v < n; ++v) {
      const Eigen::Vector2d a = o.row(v), d = Eigen::Vector2d(o.row((v + 1) % n)) - a;
      const double t = std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
      const double dist = (a + t * d - q).norm();
      if (dist < best) best = dist, edge = v, best_t = t;
    }
    const double length = (o.row((edge + 1) % n) - o.row(edge)).norm();
    if (best_t * length <= kNotchVertexMm || (1 - best_t) * length <= kNotchVertexMm) {
      notches.insert(best_t < 0.5 ? edge : (edge + 1) % n);
      continue;
    }
    Outline out(n + 1, 2);
    out.topRows(edge + 1) = o.topRows(edge + 1);
    out.row(edge + 1) = o.row(edge) + best_t * (o.row((edge + 1) % n) - o.row(edge));
    out.bottomRows(n - edge - 1) = o.bottomRows(n - edge - 1);
    o = out;
    std::set<int> moved;
    for (int v : notches) moved.insert(v > edge ? v + 1 : v);
    moved.insert(edge + 1);
    notches = moved;
    ++added;
  }
  piece->notches.assign(notches.begin(), notches.end());
  if (added > 0)
    notes->push_back("piece '" + piece->name + "': " + std::to_string(added) +
                     " notch(es) between sew-line vertices; a vertex was added at each, so "
                     "the notch keeps its place along its seam");
}

Piece BuildPiece(const RawBlock& block, const Insert& insert, double unit, const std::string& what,
                 std::vector<std::string>* notes) {
  const double c = std::cos(insert.angle_deg * M_PI / 180),
               s = std::sin(insert.angle_deg * M_PI / 180);
  auto place = [&](const Eigen::Vector2d& p) -> Eigen::Vector2d {
    const Eigen::Vector2d q = p.cwiseProduct(insert.scale);
    return unit * (Eigen::Vector2d(c * q.x() - s * q.y(), s * q.x() + c * q.y()) + insert.at);
  };
  Piece piece;
  piece.name = block.name;
  const Entity* sew = nullptr;
  const Entity* cut = nullptr;
  for (const Entity& e : block.entities) {
    const bool poly = (e.type == "POLYLINE" || e.type == "LWPOLYLINE") && e.points.size() >= 3;
    if (!poly) continue;
    if (e.layer == "14") sew = &e;
    if (e.layer == "1" && (!cut || e.points.size() > cut->points.size())) cut = &e;
  }
  if (!sew)
    for (const Entity& e : block.entities)
      if ((e.type == "POLYLINE" || e.type == "LWPOLYLINE") && e.layer == "8" && e.closed &&
          (!sew || e.points.size() > sew->points.size()))
        sew = &e;
  if (!sew) sew = cut;
  if (!sew) throw InputError(what + ": block '" + block.name + "' has no closed outline");
  std::vector<Eigen::Vector2d> pts;
  for (const Eigen::Vector2d& p : sew->points) pts.push_back(place(p));
  piece.outline = Clean(pts);
  std::vector<Eigen::Vector2d> notch_points;
  bool named = false;
  for (const Entity& e : block.entities) {
    if (&e == sew || &e == cut) continue;
    const Eigen::Vector2d p0 = place({Get(e, 10, 0, what), Get(e, 20, 0, what)});
    const Eigen::Vector2d p1 = place({Get(e, 11, 0, what), Get(e, 21, 0, what)});
    if ((e.type == "POLYLINE" || e.type == "LWPOLYLINE") && e.layer == "8") {
      std::vector<Eigen::Vector2d> line;
      for (const Eigen::Vector2d& p : e.points) line.push_back(place(p));
      if (e.closed) line.push_back(line.front());
      Outline o(static_cast<Eigen::Index>(line.size()), 2);
      for (size_t i = 0; i < line.size(); ++i) o.row(i) = line[i].transpose();
      piece.internal_lines.push_back(o);
    } else if (e.layer == "4" && (e.type == "POINT" || e.type == "LINE")) {
      notch_points.push_back(p0);
    } else if (e.layer == "7" && e.type == "LINE") {
      piece.has_grain = true;
      piece.grain_start = p0;
      piece.grain_end = p1;
    } else if (e.type == "TEXT" && e.layer == "1") {
      const std::string text = GetText(e, 1);
      if (text.rfind("Cut ", 0) != 0 && !named && !text.empty()) {
        piece.name = text;  // the readable name Valentina and we write first
        named = true;
      } else if (text.rfind("Cut ", 0) == 0) {
        try {
          piece.cut_count = std::max(1, std::stoi(text.substr(4)));
        } catch (const std::exception&) {
        }
      }
    }
  }
  PlaceNotches(notch_points, &piece, notes);
  return piece;
}

}  // namespace

Pattern PatternFromDxf(const std::string& text, const std::string& what) {
  const std::vector<Pair> pairs = Tokenise(text, what);
  double unit = 1.0;
  std::vector<RawBlock> blocks;
  std::map<std::string, Insert> inserts;
  for (size_t i = 0; i + 1 < pairs.size(); ++i) {
    if (pairs[i].code == 9 && pairs[i].value == "$INSUNITS") {
      const int u = static_cast<int>(Number(pairs[i + 1], what));
      unit = u == 1 ? 25.4 : u == 5 ? 10.0 : u == 6 ? 1000.0 : 1.0;
    }
    if (pairs[i].code != 0 || pairs[i].value != "SECTION" || pairs[i + 1].code != 2) continue;
    const std::string section = pairs[i + 1].value;
    size_t end = i + 2;
    while (end < pairs.size() && !(pairs[end].code == 0 && pairs[end].value == "ENDSEC")) ++end;
    if (end == pairs.size()) throw InputError(what + ": section " + section + " has no ENDSEC");
    const std::vector<Entity> entities = Entities(pairs, i + 2, end, what);
    if (section == "BLOCKS") {
      for (const Entity& e : entities) {
        if (e.type == "BLOCK")
          blocks.push_back({GetText(e, 2), {}});
        else if (e.type != "ENDBLK" && !blocks.empty())
          blocks.back().entities.push_back(e);
      }
    } else if (section == "ENTITIES") {
      for (const Entity& e : entities)
        if (e.type == "INSERT")
          inserts[GetText(e, 2)] = {{Get(e, 10, 0, what), Get(e, 20, 0, what)},
                                    {Get(e, 41, 1, what), Get(e, 42, 1, what)},
                                    Get(e, 50, 0, what)};
    }
    i = end;
  }
  Pattern pattern;
  pattern.name = std::filesystem::path(what).stem().string();
  pattern.source = what;
  for (const RawBlock& block : blocks) {
    if (block.name.empty() || block.name[0] == '*' || block.name[0] == '$') continue;
    if (block.entities.empty()) continue;
    const auto it = inserts.find(block.name);
    Piece piece =
        BuildPiece(block, it == inserts.end() ? Insert{} : it->second, unit, what, &pattern.notes);
    if (pattern.FindPiece(piece.name) >= 0) piece.name = block.name;  // keep names unique
    pattern.pieces.push_back(std::move(piece));
  }
  if (pattern.pieces.empty()) throw InputError(what + ": no pattern pieces (BLOCKs) found");
  MakeCounterClockwise(&pattern);
  ValidatePattern(pattern, what);
  return pattern;
}

Pattern ReadPatternDxf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the DXF file");
  std::ostringstream text;
  text << in.rdbuf();
  return PatternFromDxf(text.str(), file.string());
}

}  // namespace bespoke
