// Writes the fuzzers' seed corpus: small valid files of every format and
// encoding, made by Bespoke's own writers plus a few hand-written variants
// the writers never produce (OBJ groups and corner forms, COFF, ascii STL,
// an organised PCD with NaNs). Usage: make_fuzz_seeds OUT_DIR
// (creates OUT_DIR/{ply,pcd,obj,xyz,off,stl}/).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace {

using bespoke::PcdEncoding;
using bespoke::PlyEncoding;
using bespoke::WriteOptions;

bespoke::PointCloud SmallCloud() {
  bespoke::PointCloud cloud;
  const int n = 6;
  cloud.points.resize(n, 3);
  cloud.normals.resize(n, 3);
  cloud.colors.resize(n, 3);
  Eigen::VectorXd intensity(n);
  for (int i = 0; i < n; ++i) {
    cloud.points.row(i) << 0.1 * i, 1.7 - 0.2 * i, 0.05 * i * i;
    cloud.normals.row(i) << 0, std::sin(i), std::cos(i);
    cloud.colors.row(i) << 40 * i, 255 - 40 * i, 7;
    intensity[i] = 0.5 * i;
  }
  cloud.scalars["intensity"] = intensity;
  return cloud;
}

bespoke::TriangleMesh SmallMesh() {
  bespoke::TriangleMesh mesh;
  mesh.vertices.resize(5, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1;
  mesh.faces.resize(4, 3);
  mesh.faces << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4;
  return mesh;
}

void Text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_fuzz_seeds OUT_DIR\n";
    return 1;
  }
  const std::filesystem::path out = argv[1];
  try {
    for (const char* sub : {"ply", "pcd", "obj", "xyz", "off", "stl"}) {
      std::filesystem::create_directories(out / sub);
    }
    const bespoke::PointCloud cloud = SmallCloud();
    const bespoke::TriangleMesh mesh = SmallMesh();
    WriteOptions w;
    w.comment = "seed";
    for (const auto& [encoding, name] : {std::pair{PlyEncoding::kAscii, "ascii"},
                                         {PlyEncoding::kBinaryLittleEndian, "le"},
                                         {PlyEncoding::kBinaryBigEndian, "be"}}) {
      w.ply_encoding = encoding;
      bespoke::WriteScan(w, cloud, out / "ply" / (std::string("cloud_") + name + ".ply"));
      bespoke::WriteMesh(w, mesh, out / "ply" / (std::string("mesh_") + name + ".ply"));
    }
    for (const auto& [encoding, name] : {std::pair{PcdEncoding::kAscii, "ascii"},
                                         {PcdEncoding::kBinary, "binary"},
                                         {PcdEncoding::kBinaryCompressed, "compressed"}}) {
      w.pcd_encoding = encoding;
      bespoke::WriteScan(w, cloud, out / "pcd" / (std::string("cloud_") + name + ".pcd"));
    }
    Text(out / "pcd" / "organised.pcd",
         "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
         "WIDTH 2\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n"
         "1 2 3 4278190335\nnan nan nan 0\n4 5 6 65280\n7 8 9 255\n");
    bespoke::WriteMesh(w, mesh, out / "obj" / "mesh.obj");
    Text(out / "obj" / "groups.obj",
         "mtllib m.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0 1 0.5 0\nvt 0 0\nvt 1 1\n"
         "vn 0 0 1\ng body\nusemtl skin\ns off\nf 1/1/1 2/2/1 3/1/1 4/2/1\ng arm\nf -4//1 -3//1 "
         "-1//1\n"
         "f 2/1 3/2 4/1\n");
    bespoke::WriteScan(w, cloud, out / "xyz" / "cloud.xyz");
    bespoke::WriteScan(w, cloud, out / "xyz" / "cloud.csv");
    Text(out / "xyz" / "plain.xyz", "1 2 3\n4 5 6\n7 8 9\n");
    Text(out / "xyz" / "normals.txt", "# x y z nx ny nz\n1 2 3 0 0 1\n4 5 6 0 1 0\n");
    Text(out / "xyz" / "count.pts", "2\n1 2 3 10 255 0 0\n4 5 6 20 0 255 0\n");
    bespoke::WriteMesh(w, mesh, out / "off" / "mesh.off");
    Text(out / "off" / "coff.off",
         "COFF 3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 1.0 0 1\n0 1 0 0 0 9 9\n"
         "3 0 1 2 1 1 1\n");
    Text(out / "off" / "noff.off",
         "NOFF\n# normals\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n"
         "3 0 1 2\n");
    bespoke::WriteMesh(w, mesh, out / "stl" / "mesh.stl");
    Text(out / "stl" / "ascii.stl",
         "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
         "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
         "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
  } catch (const std::exception& e) {
    std::cerr << "make_fuzz_seeds: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
