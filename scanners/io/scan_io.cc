// The front door of scanners/io: format detection, the shared finishing of
// every reader's output (non-finite points, units, report) and the writers'
// dispatch by extension.
#include "scanners/io/scan_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <vector>

#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"

namespace bespoke {
namespace {

using io::Fail;

std::string LowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The first token of the first line that is neither blank nor a '#' comment.
std::string_view FirstToken(std::string_view bytes) {
  io::LineCursor lines(bytes.substr(0, std::min<std::size_t>(bytes.size(), 64 * 1024)));
  std::string_view line;
  std::vector<std::string_view> tokens;
  while (lines.Next(&line)) {
    if (io::Tokenize(line, &tokens) == 0 || tokens[0].front() == '#') continue;
    return tokens[0];
  }
  return {};
}

bool IsOffKeyword(std::string_view token) {
  if (token.size() < 3 || token.substr(token.size() - 3) != "OFF") return false;
  return token.substr(0, token.size() - 3).find_first_not_of("STCN4n") == std::string_view::npos;
}

std::optional<FileFormat> FormatFromExtension(const std::string& ext) {
  if (ext == ".ply") return FileFormat::kPly;
  if (ext == ".pcd") return FileFormat::kPcd;
  if (ext == ".obj") return FileFormat::kObj;
  if (ext == ".off") return FileFormat::kOff;
  if (ext == ".stl") return FileFormat::kStl;
  if (ext == ".xyz" || ext == ".xyzn" || ext == ".csv" || ext == ".txt" || ext == ".asc" ||
      ext == ".pts")
    return FileFormat::kXyz;
  return std::nullopt;
}

FileFormat DetectFormat(const std::filesystem::path& file, std::string_view bytes) {
  if (bytes.empty()) Fail(file, "file is empty");
  io::LineCursor lines(bytes.substr(0, std::min<std::size_t>(bytes.size(), 256)));
  std::string_view first;
  lines.Next(&first);
  if (io::Trim(first) == "ply") return FileFormat::kPly;
  const std::string_view token = FirstToken(io::StripBom(bytes));
  if (token == "VERSION" || token == "FIELDS") return FileFormat::kPcd;
  if (IsOffKeyword(token)) return FileFormat::kOff;
  if (io::LooksLikeBinaryStl(bytes)) return FileFormat::kStl;
  const std::string ext = LowerExtension(file);
  if (token == "solid" && (ext == ".stl" || bytes.find("facet") != std::string_view::npos))
    return FileFormat::kStl;
  if (const auto format = FormatFromExtension(ext)) return *format;
  static const char* kObjKeys[] = {"v", "vn", "vt", "f", "g", "o", "mtllib", "usemtl", "s"};
  for (const char* key : kObjKeys) {
    if (token == key) return FileFormat::kObj;
  }
  double number = 0.0;
  if (io::ParseDouble(token, &number)) return FileFormat::kXyz;
  Fail(file,
       "unknown file format: not PLY, PCD, OBJ, OFF, STL or XYZ text by content, and "
       "the extension '" +
           ext + "' does not say");
}

io::RawScan ReadRaw(const ReadOptions& options, const std::filesystem::path& file,
                    std::string_view bytes, FileFormat* format) {
  options.Check();
  *format = DetectFormat(file, bytes);
  switch (*format) {
    case FileFormat::kPly:
      return io::ReadPly(options, file, bytes);
    case FileFormat::kPcd:
      return io::ReadPcd(options, file, bytes);
    case FileFormat::kObj:
      return io::ReadObj(options, file, bytes);
    case FileFormat::kXyz:
      return io::ReadXyz(options, file, bytes);
    case FileFormat::kOff:
      return io::ReadOff(options, file, bytes);
    case FileFormat::kStl:
      return io::ReadStl(options, file, bytes);
  }
  throw InternalError("unhandled file format");
}

ReadReport MakeReport(const std::filesystem::path& file, FileFormat format,
                      const io::RawScan& raw) {
  ReadReport report;
  report.file = file;
  report.format = format;
  report.encoding = raw.encoding;
  report.fields = raw.fields;
  report.points_in_file = raw.cloud.size();
  report.faces_in_file = raw.faces_in_file;
  report.warnings = raw.warnings;
  return report;
}

Eigen::AlignedBox3d BoundsOf(const Eigen::MatrixX3d& points) {
  Eigen::AlignedBox3d box;
  if (points.rows() > 0) {
    box.min() = points.colwise().minCoeff().transpose();
    box.max() = points.colwise().maxCoeff().transpose();
  }
  return box;
}

std::string Number(double value) {
  std::string out;
  io::AppendNumber(&out, value);
  return out;
}

// The largest side of the box holding the central 98 % of the points on each
// axis (1 % trimmed at either end): a raw scan's flying pixels and clutter
// (a few percent, some metres away) must not decide the unit.
double RobustExtent(const Eigen::MatrixX3d& points) {
  const Eigen::Index n = points.rows();
  if (n == 0) return 0.0;
  const Eigen::Index cut = n / 100;
  double extent = 0.0;
  std::vector<double> values(static_cast<std::size_t>(n));
  for (int axis = 0; axis < 3; ++axis) {
    for (Eigen::Index i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = points(i, axis);
    auto low = values.begin() + cut, high = values.end() - 1 - cut;
    std::nth_element(values.begin(), low, values.end());
    const double low_value = *low;
    std::nth_element(low, high, values.end());
    extent = std::max(extent, *high - low_value);
  }
  return extent;
}

// The unit: given, else guessed from the full box, else (outliers) from the
// central 98 % of the points.
std::optional<LengthUnit> ResolveUnit(const ReadOptions& options, const ReadReport& report,
                                      const Eigen::MatrixX3d& points) {
  if (options.units) return options.units;
  const Eigen::AlignedBox3d& box = report.bounds_file_units;
  if (box.isEmpty()) return std::nullopt;
  if (auto unit = GuessLengthUnit(box.sizes().maxCoeff())) return unit;
  return GuessLengthUnit(RobustExtent(points));
}

std::string UnitProblem(const ReadReport& report, const Eigen::MatrixX3d& points) {
  const Eigen::AlignedBox3d& box = report.bounds_file_units;
  const double extent = box.isEmpty() ? 0.0 : box.sizes().maxCoeff();
  return "cannot tell the length unit: the largest side of the bounding box is " + Number(extent) +
         " file units (" + Number(RobustExtent(points)) +
         " without the outermost 1 % of points on each side), which is not a body's size "
         "(0.5 m to 2.6 m) in mm, cm, dm or m";
}

Scan FinishScan(const ReadOptions& options, const std::filesystem::path& file, FileFormat format,
                io::RawScan raw) {
  Scan scan;
  ReadReport& report = scan.report;
  report = MakeReport(file, format, raw);
  std::vector<Eigen::Index> keep;
  keep.reserve(static_cast<std::size_t>(raw.cloud.size()));
  for (Eigen::Index i = 0; i < raw.cloud.size(); ++i) {
    if (raw.cloud.points.row(i).allFinite()) keep.push_back(i);
  }
  report.non_finite_dropped = raw.cloud.size() - static_cast<std::int64_t>(keep.size());
  scan.cloud = report.non_finite_dropped > 0 ? raw.cloud.Select(keep) : std::move(raw.cloud);
  if (scan.cloud.size() < options.min_finite_points) {
    Fail(file, "only " + std::to_string(scan.cloud.size()) + " finite points (" +
                   std::to_string(report.non_finite_dropped) +
                   " NaN/Inf points dropped); a body scan needs at least " +
                   std::to_string(options.min_finite_points));
  }
  if (scan.cloud.has_normals() && !scan.cloud.normals.allFinite()) {
    scan.cloud.normals.resize(0, 3);
    report.warnings.push_back("normals dropped: some finite points have NaN/Inf normals");
  }
  report.bounds_file_units = BoundsOf(scan.cloud.points);
  const auto unit = ResolveUnit(options, report, scan.cloud.points);
  if (!unit)
    Fail(file, UnitProblem(report, scan.cloud.points) + "; give it with --units mm|cm|dm|m");
  report.unit = *unit;
  report.unit_guessed = !options.units.has_value();
  scan.cloud.points *= MillimetresPer(*unit);
  return scan;
}

Mesh FinishMesh(const ReadOptions& options, const std::filesystem::path& file, FileFormat format,
                io::RawScan raw) {
  if (format == FileFormat::kPcd || format == FileFormat::kXyz) {
    Fail(file, "is a point cloud (" + ToString(format) + "); a mesh with faces is needed");
  }
  if (raw.faces.rows() == 0) Fail(file, "has no faces; a mesh with faces is needed");
  Mesh mesh;
  mesh.report = MakeReport(file, format, raw);
  for (Eigen::Index i = 0; i < raw.cloud.size(); ++i) {
    if (!raw.cloud.points.row(i).allFinite()) {
      Fail(file, "vertex " + std::to_string(i) + " has a NaN/Inf coordinate");
    }
  }
  mesh.report.bounds_file_units = BoundsOf(raw.cloud.points);
  const auto unit = ResolveUnit(options, mesh.report, raw.cloud.points);
  if (unit) {
    mesh.report.unit = *unit;
    mesh.report.unit_guessed = !options.units.has_value();
  } else {
    mesh.report.warnings.push_back(UnitProblem(mesh.report, raw.cloud.points) + "; reported as mm");
  }
  mesh.mesh.vertices = std::move(raw.cloud.points);
  mesh.mesh.faces = std::move(raw.faces);
  mesh.face_group = std::move(raw.face_group);
  mesh.group_names = std::move(raw.group_names);
  return mesh;
}

}  // namespace

std::string ToString(FileFormat format) {
  switch (format) {
    case FileFormat::kPly:
      return "PLY";
    case FileFormat::kPcd:
      return "PCD";
    case FileFormat::kObj:
      return "OBJ";
    case FileFormat::kXyz:
      return "XYZ";
    case FileFormat::kOff:
      return "OFF";
    case FileFormat::kStl:
      return "STL";
  }
  return "unknown";
}

void ReadOptions::Check() const {
  if (max_elements < 1 || max_elements > std::numeric_limits<int>::max()) {
    throw InputError("max_elements must be between 1 and " +
                     std::to_string(std::numeric_limits<int>::max()) + ", not " +
                     std::to_string(max_elements));
  }
  if (min_finite_points < 0) {
    throw InputError("min_finite_points must be >= 0, not " + std::to_string(min_finite_points));
  }
}

Scan ReadScanFromBytes(const ReadOptions& options, const std::filesystem::path& file,
                       std::string_view bytes) {
  FileFormat format = FileFormat::kPly;
  io::RawScan raw = ReadRaw(options, file, bytes, &format);
  return FinishScan(options, file, format, std::move(raw));
}

Mesh ReadMeshFromBytes(const ReadOptions& options, const std::filesystem::path& file,
                       std::string_view bytes) {
  FileFormat format = FileFormat::kPly;
  io::RawScan raw = ReadRaw(options, file, bytes, &format);
  return FinishMesh(options, file, format, std::move(raw));
}

Scan ReadScan(const ReadOptions& options, const std::filesystem::path& file) {
  options.Check();
  const io::MappedFile mapped(file);
  return ReadScanFromBytes(options, file, mapped.bytes());
}

Mesh ReadMesh(const ReadOptions& options, const std::filesystem::path& file) {
  options.Check();
  const io::MappedFile mapped(file);
  return ReadMeshFromBytes(options, file, mapped.bytes());
}

void WriteScan(const WriteOptions& options, const PointCloud& cloud,
               const std::filesystem::path& file) {
  const std::string ext = LowerExtension(file);
  std::string contents;
  if (ext == ".ply") {
    contents = io::WritePly(options, cloud, Eigen::MatrixX3i(0, 3));
  } else if (ext == ".pcd") {
    contents = io::WritePcd(options, cloud);
  } else if (ext == ".xyz" || ext == ".txt" || ext == ".csv") {
    contents = io::WriteXyz(options, cloud, ext == ".csv" ? ',' : ' ');
  } else {
    throw InputError(file, "cannot write a point cloud as '" + ext + "': use .ply, .pcd or .xyz");
  }
  WriteFileAtomically(file, contents);
}

void WriteMesh(const WriteOptions& options, const TriangleMesh& mesh,
               const std::filesystem::path& file) {
  mesh.CheckIndices();
  const std::string ext = LowerExtension(file);
  std::string contents;
  if (ext == ".obj") {
    contents = io::WriteObj(options, mesh);
  } else if (ext == ".ply") {
    PointCloud cloud;
    cloud.points = mesh.vertices;
    contents = io::WritePly(options, cloud, mesh.faces);
  } else if (ext == ".off") {
    contents = io::WriteOff(options, mesh);
  } else if (ext == ".stl") {
    contents = io::WriteStl(options, mesh);
  } else {
    throw InputError(file, "cannot write a mesh as '" + ext + "': use .obj, .ply, .off or .stl");
  }
  WriteFileAtomically(file, contents);
}

}  // namespace bespoke
