// A stand-in for `bespoke run` in the batch tests (`bespoke batch --worker`).
//
// It takes the same command line (run SCAN -o DIR --scan-id ID ...) and keeps
// the same contract (outputs atomic, done.json last, "error: ..." on stderr
// and exit 1 for bad input, exit 2 for internal errors), but its "scan" is a
// text file of directives, so the tests can make a worker misbehave on
// purpose and fast:
//   sleep S          wait S seconds first (any directive may follow)
//   ok V             measurements.json with stature V and waist_girth V/2, done.json ok
//   input-error MSG  done.json failed + "error: <scan>: MSG", exit 1
//   crash            write an output, then SIGSEGV
//   abort            std::abort() (SIGABRT)
//   hang             sleep forever (the batch's time limit must kill it)
//   oom              allocate and touch memory until std::bad_alloc, exit 2 like bespoke
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "pipeline/batch/done_record.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/json_io.h"

namespace fs = std::filesystem;
using nlohmann::json;

int Run(int argc, char** argv) {
  std::string scan, out, id;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "run") continue;
    if (a == "-o" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--scan-id" && i + 1 < argc)
      id = argv[++i];
    else if ((a == "--design" || a == "--units" || a == "--landmarks" || a == "--threads") &&
             i + 1 < argc)
      ++i;
    else if (scan.empty())
      scan = a;
  }
  if (scan.empty() || out.empty()) {
    std::cerr << "error: fake_worker: usage: run SCAN -o DIR\n";
    return 1;
  }
  bespoke::DoneRecord record;
  record.status = "ok";
  record.scan_id = id;
  record.input = scan;
  std::error_code ec;
  fs::create_directories(out, ec);
  std::ifstream in(scan);
  if (!in) {
    std::cerr << "error: " << scan << ": cannot open\n";
    return 1;
  }
  record.input_size_bytes = static_cast<std::int64_t>(fs::file_size(scan));
  record.input_sha256 = bespoke::FileSha256(scan);
  std::string word;
  while (in >> word) {
    if (word == "sleep") {
      double s = 0;
      in >> s;
      std::this_thread::sleep_for(std::chrono::duration<double>(s));
    } else if (word == "ok") {
      double v = 0;
      in >> v;
      const json doc = {
          {"format", "bespoke-measurements"},
          {"version", 1},
          {"units", "mm"},
          {"frame", "body"},
          {"landmarks", json::object()},
          {"measurements",
           {{{"name", "stature"}, {"kind", "height"}, {"value_mm", v}, {"flags", json::array()}},
            {{"name", "waist_girth"},
             {"kind", "girth"},
             {"value_mm", v / 2},
             {"flags", v > 1900 ? json::array({"section_open"}) : json::array()}}}}};
      bespoke::WriteJsonFile(fs::path(out) / "measurements.json", doc);
      record.outputs.push_back(bespoke::DescribeOutput(out, "measurements.json"));
      record.results["points_cleaned"] = static_cast<std::int64_t>(v * 10);
      record.steps.push_back({{"name", "fake"}, {"time_s", 0.001}});
      bespoke::WriteDoneRecord(out, record);
      return 0;
    } else if (word == "input-error") {
      std::string message;
      std::getline(in, message);
      message = scan + ":" + message;
      record.status = "failed";
      record.failure = bespoke::ScanFailure{"input_error", message, 1, 0, ""};
      bespoke::WriteDoneRecord(out, record);
      std::cerr << "error: " << message << "\n";
      return 1;
    } else if (word == "crash") {
      bespoke::WriteFileAtomically(fs::path(out) / "partial.txt", "half\n");
      // The default action, so the process dies by the signal in every build:
      // AddressSanitizer's handler would otherwise report and exit with 1.
      std::signal(SIGSEGV, SIG_DFL);
      std::raise(SIGSEGV);
    } else if (word == "abort") {
      std::abort();
    } else if (word == "hang") {
      for (;;) ::pause();
    } else if (word == "oom") {
      std::vector<std::unique_ptr<char[]>> blocks;
      try {
        for (;;) {
          blocks.emplace_back(new char[64 << 20]);
          for (size_t i = 0; i < (64u << 20); i += 4096) blocks.back()[i] = 1;
        }
      } catch (const std::bad_alloc&) {
        blocks.clear();
        std::cerr << "critical: internal error: out of memory\n";
        return 2;
      }
    } else {
      std::cerr << "critical: internal error: fake_worker: unknown directive " << word << "\n";
      return 2;
    }
  }
  std::cerr << "error: " << scan << ": no directive\n";
  return 1;
}

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
