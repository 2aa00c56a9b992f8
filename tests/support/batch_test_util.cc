#include "tests/support/batch_test_util.h"

#include <fstream>
#include <sstream>

namespace bespoke::testing {
namespace fs = std::filesystem;

fs::path BespokeBinary() { return BESPOKE_BINARY; }
fs::path FakeWorkerBinary() { return BESPOKE_FAKE_WORKER; }

pid_t StartBespoke(const std::vector<std::string>& args, const fs::path& log) {
  SpawnOptions spawn;
  spawn.executable = BespokeBinary();
  spawn.argv = {BespokeBinary().string()};
  spawn.argv.insert(spawn.argv.end(), args.begin(), args.end());
  spawn.log_file = log;
  return SpawnWorker(spawn);
}

int RunBespoke(const std::vector<std::string>& args, const fs::path& log) {
  const WorkerExit exit = ReapWorker(StartBespoke(args, log));
  return exit.signaled ? 128 + exit.signal : exit.exit_code;
}

void WriteText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

int CountDone(const fs::path& out_dir) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out_dir, ec)) {
    if (e.is_directory() && fs::exists(e.path() / "done.json")) ++n;
  }
  return n;
}

std::vector<std::string> CsvRows(const std::string& csv) {
  std::vector<std::string> rows;
  std::istringstream in(csv);
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (header) {
      header = false;
      continue;
    }
    if (!line.empty()) rows.push_back(line);
  }
  return rows;
}

}  // namespace bespoke::testing
