// done.json: the record that says one scan's output folder is complete.
//
// `bespoke run` writes every output of a scan atomically into its folder and
// then, LAST, done.json: status, timings, versions, settings, and every output
// file with its size and SHA-256. A folder without a valid done.json is
// partial (the job was interrupted) and is redone by `bespoke batch --resume`.
// When a worker fails, the batch writes done.json with status "failed" and
// the reason, so failures are final too (redone only with --retry-failed).
//
//   {"format": "bespoke-scan-done", "version": 1, "status": "ok",
//    "scan_id": "subject_001", "input": "/data/subject_001.ply",
//    "input_size_bytes": 1234, "input_sha256": "...",
//    "results": {"points_cleaned": 51234, ...},       // flat, for the summary
//    "failure": {"kind": "input_error", "message": "...", ...},  // when failed
//    "steps": [{"name": "clean", "time_s": 1.2}], "time_s": 2.9,
//    "versions": {...}, "settings": {...},
//    "outputs": [{"file": "measurements.json", "size_bytes": 2048, "sha256": "..."}]}
#ifndef BESPOKE_PIPELINE_BATCH_DONE_RECORD_H_
#define BESPOKE_PIPELINE_BATCH_DONE_RECORD_H_

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace bespoke {

inline constexpr const char* kDoneFileName = "done.json";

// Why a scan failed. The kind decides the batch's exit code (input_error -> 1,
// anything else -> 2) and is a column of failures.csv.
struct ScanFailure {
  std::string kind;  // input_error | internal_error | out_of_memory | timeout | crash | not_started
  std::string message;   // one line a user can act on; deterministic (no pids, no times)
  int exit_code = -1;    // the worker's exit code, -1 when it was killed by a signal
  int signal = 0;        // the signal that ended the worker, 0 when it exited
  std::string log_tail;  // the last lines of the worker's log
};

struct OutputFile {
  std::string file;  // relative to the scan's folder, '/' separated
  std::int64_t size_bytes = 0;
  std::string sha256;  // lower-case hex
};

struct DoneRecord {
  std::string status;  // "ok" or "failed"
  std::string scan_id;
  std::string input;
  std::int64_t input_size_bytes = -1;                 // -1 when the input is not a regular file
  std::string input_sha256;                           // "" when not a regular file
  nlohmann::json results = nlohmann::json::object();  // flat name -> number/string
  std::optional<ScanFailure> failure;
  nlohmann::json steps = nlohmann::json::array();  // [{"name", "time_s", ...}]
  double time_s = 0;                               // wall time of the job
  nlohmann::json versions = nlohmann::json::object();
  nlohmann::json settings = nlohmann::json::object();
  std::vector<OutputFile> outputs;
  std::string finished_utc;  // ISO 8601
  // Added by the batch after the worker ended: wall_s, user_s, system_s,
  // max_rss_mb, exit_code, signal (run-to-run varying; never in summary.csv).
  nlohmann::json worker = nlohmann::json::object();

  nlohmann::json ToJson() const;
  // InputError when `j` is not a done record.
  static DoneRecord FromJson(const nlohmann::json& j, const std::string& what);
};

// Lower-case hex SHA-256 of a regular file's bytes; InputError when unreadable.
std::string FileSha256(const std::filesystem::path& file);

// Size and hash of `dir/relative`.
OutputFile DescribeOutput(const std::filesystem::path& dir, const std::string& relative);

// Writes dir/done.json atomically (stamps finished_utc when empty).
void WriteDoneRecord(const std::filesystem::path& dir, DoneRecord record);

// Reads dir/done.json and checks it: parses, has the right format, and every
// listed output exists with its recorded size (and SHA-256 when
// `verify_hashes`). nullopt when absent or invalid; `problem` (if given) then
// says why ("missing", "measurements.json: size 10, recorded 2048", ...).
std::optional<DoneRecord> ReadValidDoneRecord(const std::filesystem::path& dir, bool verify_hashes,
                                              std::string* problem = nullptr);

// "2024-05-01T12:00:00Z" for now.
std::string UtcNow();

// The versions of Bespoke and its main libraries, for done.json and reports.
nlohmann::json BuildVersions();

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_DONE_RECORD_H_
