#include "pipeline/batch/scan_worker.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "pipeline/batch/process.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The message of the last "error: ..." / "critical: internal error: ..." log line.
std::string LastErrorLine(const std::string& log) {
  std::istringstream lines(log);
  std::string line, found;
  while (std::getline(lines, line)) {
    for (const char* prefix : {"error: ", "critical: internal error: ", "critical: "}) {
      if (line.rfind(prefix, 0) == 0) {
        found = line.substr(std::string(prefix).size());
        break;
      }
    }
  }
  return found;
}

bool MentionsOutOfMemory(const std::string& text) {
  return text.find("out of memory") != std::string::npos ||
         text.find("bad_alloc") != std::string::npos ||
         text.find("Cannot allocate memory") != std::string::npos;
}

ScanFailure Classify(const WorkerSettings& settings, const WorkerResult& r,
                     const std::string& worker_message, const std::string& log,
                     const std::string& problem) {
  ScanFailure f;
  f.exit_code = r.exit.signaled ? -1 : r.exit.exit_code;
  f.signal = r.exit.signaled ? r.exit.signal : 0;
  f.log_tail = log;
  const std::string message = !worker_message.empty() ? worker_message : LastErrorLine(log);
  if (r.timed_out) {
    f.kind = "timeout";
    f.message = fmt::format("timed out after {:g} s; the worker was killed", settings.timeout_s);
  } else if (r.exit.signaled) {
    f.kind = "crash";
    f.message = "the worker crashed: " + DescribeSignal(r.exit.signal);
    if (r.exit.signal == 9)
      f.message += " not sent by the batch (the kernel's out-of-memory killer?)";
    if (!message.empty()) f.message += "; last error: " + message;
  } else if (r.exit.exit_code == 1) {
    f.kind = "input_error";
    f.message = message.empty() ? "bad input (exit code 1, no message)" : message;
  } else if (r.exit.exit_code == 2 && MentionsOutOfMemory(message)) {
    f.kind = "out_of_memory";
    f.message = settings.memory_mb > 0
                    ? fmt::format("out of memory (limit {} MB): {}", settings.memory_mb, message)
                    : "out of memory: " + message;
  } else if (r.exit.exit_code == 127) {
    f.kind = "not_started";
    f.message = message.empty() ? "the worker could not be started (exit code 127)" : message;
  } else if (r.exit.exit_code == 0) {
    f.kind = "internal_error";
    f.message = "the worker exited 0 but left no valid done.json: " + problem;
  } else {
    f.kind = "internal_error";
    f.message = message.empty() ? fmt::format("exit code {}", r.exit.exit_code) : message;
  }
  return f;
}

}  // namespace

std::vector<std::string> WorkerArguments(const WorkerSettings& settings, const ScanEntry& entry,
                                         const fs::path& folder) {
  std::vector<std::string> argv = {settings.executable.string(),
                                   "run",
                                   entry.path.string(),
                                   "-o",
                                   folder.string(),
                                   "--scan-id",
                                   entry.id};
  if (settings.threads > 0)
    argv.insert(argv.end(), {"--threads", std::to_string(settings.threads)});
  const std::string design = entry.design.empty() ? settings.design : entry.design;
  const std::string units = entry.units.empty() ? settings.units : entry.units;
  if (!design.empty()) argv.insert(argv.end(), {"--design", design});
  if (!units.empty()) argv.insert(argv.end(), {"--units", units});
  if (!entry.landmarks.empty()) argv.insert(argv.end(), {"--landmarks", entry.landmarks.string()});
  return argv;
}

std::string FileTail(const fs::path& file, int max_lines) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(0, size - 4096);
  in.seekg(start);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t pos = text.size();
  if (!text.empty() && text.back() == '\n') --pos;
  for (int n = 0; n < max_lines && pos != std::string::npos && pos > 0; ++n) {
    pos = text.rfind('\n', pos - 1);
  }
  return pos == std::string::npos || pos == 0 ? text : text.substr(pos + 1);
}

DoneRecord RecordWorkerEnd(const WorkerSettings& settings, const ScanEntry& entry,
                           const fs::path& folder, const WorkerResult& result) {
  std::string problem;
  std::optional<DoneRecord> worker_record = ReadValidDoneRecord(folder, false, &problem);
  const json worker = {{"wall_s", result.wall_s},
                       {"user_s", result.exit.user_s},
                       {"system_s", result.exit.system_s},
                       {"max_rss_mb", result.exit.max_rss_mb},
                       {"exit_code", result.exit.signaled ? -1 : result.exit.exit_code},
                       {"signal", result.exit.signaled ? result.exit.signal : 0},
                       {"timed_out", result.timed_out}};
  const bool clean_exit = !result.timed_out && !result.exit.signaled && result.exit.exit_code == 0;
  if (clean_exit && worker_record && worker_record->status == "ok") {
    worker_record->worker = worker;
    WriteDoneRecord(folder, *worker_record);
    return *worker_record;
  }
  DoneRecord record;
  if (worker_record) record = *worker_record;  // keeps the worker's steps and outputs
  const std::string worker_message =
      worker_record && worker_record->failure ? worker_record->failure->message : "";
  record.status = "failed";
  record.scan_id = entry.id;
  record.input = entry.path.string();
  record.failure =
      Classify(settings, result, worker_message, FileTail(folder / kWorkerLogName, 15), problem);
  record.worker = worker;
  record.finished_utc.clear();
  WriteDoneRecord(folder, record);
  return record;
}

}  // namespace bespoke
