// Test-only: a corpus of malformed scan files, one of each kind of damage,
// built in code. Every file must be rejected by ReadScan with default
// options (InputError naming the file) and by `bespoke info` (exit 1, the
// file named on stderr). Used by scanners/io/scan_io_test.cc and
// pipeline/cli/cmd_info_test.cc. The per-format tests hold many more cases.
#ifndef BESPOKE_TESTS_SUPPORT_MALFORMED_CORPUS_H_
#define BESPOKE_TESTS_SUPPORT_MALFORMED_CORPUS_H_

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace bespoke::testing {

struct MalformedFile {
  std::string name;      // file name (the extension matters for some)
  std::string bytes;     // contents
  std::string fragment;  // part of the expected message
};

namespace corpus_detail {

template <typename T>
void Put(std::string* out, T value) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  out->append(b, sizeof(T));
}

inline std::string PlyHeader(const std::string& format, const std::string& elements) {
  return "ply\nformat " + format + " 1.0\n" + elements + "end_header\n";
}

inline const char* XyzProps() { return "property float x\nproperty float y\nproperty float z\n"; }

// A valid binary PLY of a triangle: 3 vertices and one face.
inline std::string TrianglePly() {
  std::string s = PlyHeader("binary_little_endian",
                            "element vertex 3\n" + std::string(XyzProps()) +
                                "element face 1\nproperty list uchar int vertex_indices\n");
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (const float x : v) Put<float>(&s, x);
  Put<std::uint8_t>(&s, 3);
  for (int i = 0; i < 3; ++i) Put<std::int32_t>(&s, i);
  return s;
}

inline std::string PcdHeader(const std::string& size_line, const std::string& rest) {
  return "VERSION 0.7\nFIELDS x y z\n" + size_line + "TYPE F F F\nCOUNT 1 1 1\n" + rest;
}

// `n` points along a line `step` file units apart, as ascii PLY.
inline std::string LinePly(int n, double step) {
  std::string s = PlyHeader("ascii", "element vertex " + std::to_string(n) + "\n" + XyzProps());
  for (int i = 0; i < n; ++i) s += "0 0 " + std::to_string(i * step) + "\n";
  return s;
}

}  // namespace corpus_detail

inline std::vector<MalformedFile> MalformedCorpus() {
  using namespace corpus_detail;
  const std::string le = "binary_little_endian";
  const std::string triangle = TrianglePly();
  std::string bad_list = triangle;
  bad_list[bad_list.size() - 13] = static_cast<char>(200);  // list count 200, 12 bytes left
  std::string bad_index = triangle;
  const std::int32_t nine = 9;
  std::memcpy(&bad_index[bad_index.size() - 4], &nine, 4);
  std::string lzf_sizes = PcdHeader("SIZE 4 4 4\n", "WIDTH 1\nDATA binary_compressed\n");
  Put<std::uint32_t>(&lzf_sizes, 4);
  Put<std::uint32_t>(&lzf_sizes, 4000000);
  lzf_sizes += "abcd";
  std::string lzf_corrupt = PcdHeader("SIZE 4 4 4\n", "WIDTH 1\nDATA binary_compressed\n");
  Put<std::uint32_t>(&lzf_corrupt, 3);
  Put<std::uint32_t>(&lzf_corrupt, 12);
  lzf_corrupt += "\xe0\x05\x01";
  std::string stl(80, ' ');
  Put<std::uint32_t>(&stl, 2);
  stl += std::string(60, '\0');
  return {
      {"empty.ply", "", "file is empty"},
      {"truncated_header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
       "no 'end_header'"},
      {"truncated_data.ply", triangle.substr(0, triangle.size() - 7), "truncated"},
      {"huge_count.ply", PlyHeader(le, "element vertex 4000000000\n" + std::string(XyzProps())),
       "more than the limit"},
      {"count_beyond_file.ply",
       PlyHeader(le, "element vertex 40000000\n" + std::string(XyzProps())) + "0123456789ab",
       "only 12 bytes"},
      {"negative_count.ply", PlyHeader("ascii", "element vertex -5\n" + std::string(XyzProps())),
       "negative"},
      {"bad_type.ply", PlyHeader("ascii", "element vertex 1\nproperty float128 x\n"),
       "unknown PLY property type"},
      {"bad_list_count.ply", bad_list, "do not fit"},
      {"face_index_out_of_range.ply", bad_index, "refers to vertex 9"},
      {"wrong_token_count.ply",
       PlyHeader("ascii", "element vertex 2\n" + std::string(XyzProps())) + "1 2 3\n4 5 6 7\n",
       "expected 3 values"},
      {"junk_token.ply",
       PlyHeader("ascii", "element vertex 2\n" + std::string(XyzProps())) + "1 2 3\n4 5 #\n",
       "is not a number"},
      {"unknown_encoding.ply", PlyHeader("binary_middle_endian", ""), "unknown PLY format"},
      {"nan_only.ply",
       PlyHeader("ascii", "element vertex 2\n" + std::string(XyzProps())) +
           "nan nan nan\ninf 0 0\n",
       "only 0 finite points"},
      {"zero_points.ply", PlyHeader("ascii", "element vertex 0\n" + std::string(XyzProps())),
       "only 0 finite points"},
      {"too_few_points.ply", LinePly(10, 0.1), "at least 1000"},
      {"no_plausible_unit.ply", LinePly(1200, 1000.0), "--units"},
      {"huge_width.pcd", PcdHeader("SIZE 4 4 4\n", "WIDTH 60000\nHEIGHT 60000\nDATA binary\n"),
       "more than the limit"},
      {"truncated.pcd", PcdHeader("SIZE 4 4 4\n", "WIDTH 100\nDATA binary\n") + "0123",
       "only 4 follow"},
      {"bad_size.pcd", PcdHeader("SIZE 4 4 3\n", "WIDTH 1\nDATA ascii\n1 2 3\n"), "SIZE '3'"},
      {"points_mismatch.pcd", PcdHeader("SIZE 4 4 4\n", "WIDTH 2\nPOINTS 5\nDATA ascii\n"),
       "is not WIDTH * HEIGHT"},
      {"compressed_sizes.pcd", lzf_sizes, "unpacks to 4000000 bytes"},
      {"compressed_corrupt.pcd", lzf_corrupt, "LZF-compressed data is corrupt"},
      {"bad_face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "refers to vertex 7"},
      {"ragged.xyz", "1 2 3\n4 5 6\n7 8\n", "expected 3 values, found 2"},
      {"truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n3 0 1 2\n", "truncated"},
      {"truncated.stl", stl, "declares 2 triangles"},
      {"unknown.bin",
       "\x7f"
       "ELF\x02\x01\x01 binary junk",
       "unknown file format"},
  };
}

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_MALFORMED_CORPUS_H_
