#include "resize/io/garmentcode.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using nlohmann::json;
using V = Eigen::Vector2d;

V ReadVertex(const json& j, double scale, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    throw InputError(where + ": a vertex is [x, y]");
  return scale * V(j[0].get<double>(), j[1].get<double>());
}

V RelativeToAbsolute(const V& start, const V& end, const V& rel) {
  const V edge = end - start;
  return start + rel.x() * edge + rel.y() * V(-edge.y(), edge.x());
}

std::vector<V> ArcPoints(const V& a, const V& b, double radius, bool large, bool right, int n,
                         const std::string& where) {
  const double chord = (b - a).norm();
  if (!(radius > 0) || chord <= 0) throw InputError(where + ": bad circle arc");
  const double r = std::max(radius, chord / 2);
  const V mid = (a + b) / 2, dir = (b - a) / chord, left(-dir.y(), dir.x());
  const double h = std::sqrt(std::max(r * r - chord * chord / 4, 0.0));
  // The small arc bulges to the right when `right`; its centre is on the other side.
  const double bulge_side = right ? -1.0 : 1.0;
  const V centre = mid - bulge_side * left * h * (large ? -1.0 : 1.0);
  double a0 = std::atan2(a.y() - centre.y(), a.x() - centre.x());
  double a1 = std::atan2(b.y() - centre.y(), b.x() - centre.x());
  // Go the way round that passes the bulge side.
  const V probe = mid + bulge_side * left * (large ? r + h : r - h);
  const double ap = std::atan2(probe.y() - centre.y(), probe.x() - centre.x());
  auto wrap = [](double x) { return x < 0 ? x + 2 * M_PI : x; };
  double sweep = wrap(a1 - a0);
  if (wrap(ap - a0) > sweep) sweep -= 2 * M_PI;
  std::vector<V> points;
  for (int i = 0; i <= n; ++i) {
    const double t = a0 + sweep * i / n;
    points.push_back(centre + r * V(std::cos(t), std::sin(t)));
  }
  return points;
}

// Points of one edge from its start (inclusive) to its end (exclusive).
std::vector<V> EdgePoints(const json& edge, const V& a, const V& b, bool relative, double scale,
                          int n, const std::string& where) {
  std::vector<V> points;
  auto control = [&](const json& c) {
    const V p =
        relative ? V(c.at(0).get<double>(), c.at(1).get<double>()) : ReadVertex(c, scale, where);
    return relative ? RelativeToAbsolute(a, b, p) : p;
  };
  try {
    if (!edge.contains("curvature")) {
      points = ResamplePolyline({a, b}, n + 1);
    } else if (edge["curvature"].is_array()) {
      points = SampleQuadratic(a, control(edge["curvature"]), b, n + 1);
    } else {
      const json& c = edge["curvature"];
      const std::string type = c.at("type").get<std::string>();
      const json& p = c.at("params");
      if (type == "quadratic")
        points = SampleQuadratic(a, control(p.at(0)), b, n + 1);
      else if (type == "cubic")
        points = SampleCubic(a, control(p.at(0)), control(p.at(1)), b, n + 1);
      else if (type == "circle")
        points = ArcPoints(a, b, scale * p.at(0).get<double>(), p.at(1).get<double>() != 0,
                           p.at(2).get<double>() != 0, n, where);
      else
        throw InputError(where + ": unknown curvature type '" + type + "'");
    }
  } catch (const json::exception& e) {
    throw InputError(where + ": malformed curvature (" + std::string(e.what()) + ")");
  }
  points.pop_back();
  return points;
}

}  // namespace

void GarmentCodeOptions::Check() const {
  if (samples_per_edge < 1) throw InputError("GarmentCode import: samples_per_edge must be >= 1");
}

bool IsGarmentCode(const json& document) {
  return document.is_object() && document.contains("pattern") && document["pattern"].is_object() &&
         document["pattern"].contains("panels");
}

json ParseJsonWithComments(const std::string& text, const std::string& what) {
  try {
    return json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw InputError(what + ": " + e.what());
  }
}

Pattern PatternFromGarmentCode(const GarmentCodeOptions& options, const json& document,
                               const std::string& what) {
  options.Check();
  if (!IsGarmentCode(document)) throw InputError(what + ": not a GarmentCode pattern");
  const json properties = document.value("properties", json::object());
  const double units_in_meter = properties.value("units_in_meter", 100.0);
  if (!(units_in_meter > 0)) throw InputError(what + ": units_in_meter must be positive");
  const double scale = 1000.0 / units_in_meter;
  const bool relative = properties.value("curvature_coords", "relative") != "absolute";
  const int n = options.samples_per_edge;
  Pattern pattern;
  pattern.name = std::filesystem::path(what).stem().string();
  pattern.source = what + " (GarmentCode)";
  std::map<std::string, int> edge_count;
  std::map<std::string, bool> reversed;
  for (const auto& [name, panel] : document["pattern"]["panels"].items()) {
    const std::string where = what + ": panel '" + name + "'";
    std::vector<V> vertices;
    for (const json& v : panel.value("vertices", json::array()))
      vertices.push_back(ReadVertex(v, scale, where));
    const json edges = panel.value("edges", json::array());
    if (edges.size() < 2) throw InputError(where + " needs at least 2 edges");
    std::vector<V> outline;
    for (size_t e = 0; e < edges.size(); ++e) {
      const std::string ew = where + " edge " + std::to_string(e);
      const json ends = edges[e].value("endpoints", json::array());
      const json next = edges[(e + 1) % edges.size()].value("endpoints", json::array());
      if (ends.size() != 2 || next.size() != 2 || !ends[0].is_number_integer() ||
          !ends[1].is_number_integer())
        throw InputError(ew + ": endpoints must be two vertex ids");
      const int a = ends[0].get<int>(), b = ends[1].get<int>();
      if (a < 0 || b < 0 || a >= static_cast<int>(vertices.size()) ||
          b >= static_cast<int>(vertices.size()))
        throw InputError(ew + ": vertex id out of range");
      if (next[0] != ends[1]) throw InputError(ew + ": edges do not form a loop");
      const std::vector<V> pts =
          EdgePoints(edges[e], vertices[a], vertices[b], relative, scale, n, ew);
      outline.insert(outline.end(), pts.begin(), pts.end());
    }
    Piece piece;
    piece.name = name;
    piece.outline.resize(static_cast<Eigen::Index>(outline.size()), 2);
    for (size_t i = 0; i < outline.size(); ++i) piece.outline.row(i) = outline[i].transpose();
    reversed[name] = SignedArea(piece.outline) < 0;
    const int count = static_cast<int>(outline.size());
    if (reversed[name]) piece.outline = piece.outline.colwise().reverse().eval();
    for (size_t e = 0; e < edges.size(); ++e) {
      const int start = static_cast<int>(e) * n;
      piece.critical.push_back(reversed[name] ? (count - 1 - start) : start);
    }
    edge_count[name] = static_cast<int>(edges.size());
    pattern.pieces.push_back(std::move(piece));
  }
  int index = 0;
  for (const json& stitch : document["pattern"].value("stitches", json::array())) {
    const std::string where = what + ": stitch " + std::to_string(index++);
    if (!stitch.is_array() || stitch.size() != 2)
      throw InputError(where + ": only 1-to-1 stitches are supported");
    Seam seam;
    seam.name = "stitch_" + std::to_string(index - 1);
    SeamSide* sides[2] = {&seam.a, &seam.b};
    for (int s = 0; s < 2; ++s) {
      const std::string panel = stitch[s].value("panel", "");
      const int edge = stitch[s].value("edge", -1);
      if (!edge_count.count(panel) || edge < 0 || edge >= edge_count[panel])
        throw InputError(where + ": unknown panel/edge '" + panel + "' " + std::to_string(edge));
      const int count = edge_count[panel] * n;
      int from = edge * n, to = (edge * n + n) % count;
      bool forward = true;
      if (reversed[panel]) {
        from = count - 1 - from;
        to = count - 1 - to;
        forward = false;
      }
      *sides[s] = {panel, from, to, forward};
    }
    pattern.seams.push_back(seam);
  }
  ValidatePattern(pattern, what);
  return pattern;
}

Pattern ReadGarmentCode(const GarmentCodeOptions& options, const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return PatternFromGarmentCode(options, ParseJsonWithComments(text.str(), file.string()),
                                file.string());
}

}  // namespace bespoke
