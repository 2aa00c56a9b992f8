// TEMPORARY (removed as each format lands): formats not implemented yet say so.
#include "scanners/core/errors.h"
#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {
[[noreturn]] void NotYet(const std::string& what) {
  throw InternalError(what + " is not implemented yet");
}
}  // namespace
RawScan ReadPcd(const ReadOptions&, const std::filesystem::path& f, std::string_view) {
  Fail(f, "reading PCD is not implemented yet");
}
RawScan ReadXyz(const ReadOptions&, const std::filesystem::path& f, std::string_view) {
  Fail(f, "reading XYZ is not implemented yet");
}
RawScan ReadOff(const ReadOptions&, const std::filesystem::path& f, std::string_view) {
  Fail(f, "reading OFF is not implemented yet");
}
RawScan ReadStl(const ReadOptions&, const std::filesystem::path& f, std::string_view) {
  Fail(f, "reading STL is not implemented yet");
}
bool LooksLikeBinaryStl(std::string_view) { return false; }
std::string WritePcd(const WriteOptions&, const PointCloud&) { NotYet("writing PCD"); }
std::string WriteXyz(const WriteOptions&, const PointCloud&) { NotYet("writing XYZ"); }
std::string WriteOff(const WriteOptions&, const TriangleMesh&) { NotYet("writing OFF"); }
std::string WriteStl(const WriteOptions&, const TriangleMesh&) { NotYet("writing STL"); }
}  // namespace bespoke::io
