#include "pipeline/batch/scan_job.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <new>

#include "pipeline/batch/scan_steps.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/units.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Size and hash of the input when it is a regular file; clear errors for
// things that are not scans (a dangling link names its target).
void DescribeInput(const fs::path& scan, DoneRecord* record) {
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(scan, ec);
  if (fs::is_symlink(link) && !fs::exists(scan, ec)) {
    throw InputError(scan, "is a dangling symbolic link (to '" +
                               fs::read_symlink(scan, ec).string() + "'), not a scan file");
  }
  if (!fs::is_regular_file(scan, ec)) return;  // the reader names what it is
  record->input_size_bytes = static_cast<std::int64_t>(fs::file_size(scan, ec));
  record->input_sha256 = FileSha256(scan);
}

void RecordFailure(const fs::path& out_dir, DoneRecord record, const std::string& kind,
                   const std::string& message) {
  record.status = "failed";
  record.failure = ScanFailure{kind, message, kind == "input_error" ? 1 : 2, 0, ""};
  try {
    WriteDoneRecord(out_dir, record);
  } catch (...) {
    // the error being reported matters more; the batch records the failure itself
  }
}

void RunSteps(JobState& state) {
  for (const ScanStep& step : ScanSteps()) {
    const char* skip = step.skip_reason ? step.skip_reason(state) : nullptr;
    const bool not_built = !skip && !step.run;
    if (not_built) skip = step.unavailable;
    if (skip) {
      state.record->steps.push_back({{"name", step.name}, {"skipped", skip}});
      if (not_built) {
        spdlog::warn("{}: skipped: {}", step.name, skip);
      } else {
        spdlog::info("{}: skipped: {}", step.name, skip);
      }
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    step.run(state);
    const double t = SecondsSince(start);
    state.record->steps.push_back({{"name", step.name}, {"time_s", t}});
    spdlog::info("{}: done in {:.2f} s", step.name, t);
  }
}

}  // namespace

void ScanJobOptions::Check() const {
  if (!units.empty() && !ParseLengthUnit(units)) {
    throw InputError("--units '" + units + "': expected mm, cm, dm or m");
  }
  if (!design.empty() && design != "shirt" && design != "trousers") {
    throw InputError("--design '" + design + "': expected shirt or trousers");
  }
  std::error_code ec;
  if (!landmarks.empty() && !fs::is_regular_file(landmarks, ec)) {
    throw InputError(landmarks, "landmark override file not found");
  }
  if (threads < 0) throw InputError("--threads must be >= 0 (0 = all CPUs)");
  for (char c : scan_id) {
    if (c == '/' || c == '\0') throw InputError("--scan-id '" + scan_id + "' must not contain '/'");
  }
}

json ScanJobOptions::ToJson() const {
  return {{"scan_id", scan_id},
          {"units", units},
          {"design", design},
          {"landmarks", landmarks.string()},
          {"write_cleaned_cloud", write_cleaned_cloud},
          {"threads", threads}};
}

DoneRecord RunScanJob(const ScanJobOptions& options, const fs::path& scan, const fs::path& out_dir,
                      Progress* progress) {
  options.Check();
  const auto start = std::chrono::steady_clock::now();
  CreateDirectories(out_dir);
  std::error_code ec;
  fs::remove(out_dir / kDoneFileName, ec);  // a redone folder must not look done meanwhile
  DoneRecord record;
  record.status = "ok";
  record.scan_id = options.scan_id.empty() ? scan.stem().string() : options.scan_id;
  record.input = fs::absolute(scan, ec).lexically_normal().string();
  record.versions = BuildVersions();
  record.settings = options.ToJson();
  JobState state;
  state.options = &options;
  state.scan_file = scan;
  state.out_dir = out_dir;
  state.progress = progress;
  state.record = &record;
  try {
    DescribeInput(scan, &record);
    RunSteps(state);
  } catch (const InputError& e) {
    record.time_s = SecondsSince(start);
    RecordFailure(out_dir, record, "input_error", e.what());
    throw;
  } catch (const std::bad_alloc&) {
    record.time_s = SecondsSince(start);
    RecordFailure(out_dir, record, "internal_error", "out of memory");
    throw;
  } catch (const std::exception& e) {
    record.time_s = SecondsSince(start);
    RecordFailure(out_dir, record, "internal_error", e.what());
    throw;
  }
  record.time_s = SecondsSince(start);
  WriteDoneRecord(out_dir, record);
  return record;
}

}  // namespace bespoke
