// batch_corpus DIR [--good N] [--points P] [--hostile] [--seed S]
// Writes N synthetic body scans (good_000.ply ...) and, with --hostile, the
// ten malformed/hostile files of corpus.h into DIR. Used by
// scripts/batch-reliability.sh and scripts/bench-batch.sh until `bespoke
// scan-sim` writes the good scans.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "scanners/core/atomic_file.h"
#include "tests/support/corpus.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: batch_corpus DIR [--good N] [--points P] [--hostile] [--seed S]\n";
    return 1;
  }
  const std::filesystem::path dir = argv[1];
  int good = 10, points = 60000;
  unsigned seed = 1;
  bool hostile = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--good" && i + 1 < argc)
      good = std::atoi(argv[++i]);
    else if (a == "--points" && i + 1 < argc)
      points = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc)
      seed = static_cast<unsigned>(std::atoi(argv[++i]));
    else if (a == "--hostile")
      hostile = true;
    else {
      std::cerr << "batch_corpus: unknown argument " << a << "\n";
      return 1;
    }
  }
  try {
    bespoke::CreateDirectories(dir);
    for (int k = 0; k < good; ++k) {
      bespoke::testing::SyntheticScanOptions o;
      o.points = points;
      o.seed = seed * 1000 + k;
      o.stature_mm = 1550 + (k * 37) % 400;
      o.girth_scale = 0.85 + 0.03 * (k % 10);
      o.yaw_deg = (k * 53) % 360;
      char name[32];
      std::snprintf(name, sizeof name, "good_%03d.ply", k);
      bespoke::testing::WriteSyntheticBodyScan(o, dir / name);
    }
    if (hostile) bespoke::testing::WriteHostileFiles(dir, seed);
  } catch (const std::exception& e) {
    std::cerr << "batch_corpus: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
