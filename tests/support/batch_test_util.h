// Helpers of the batch integration tests: run `bespoke` as a separate
// process, read files, count finished scans.
#ifndef BESPOKE_TESTS_SUPPORT_BATCH_TEST_UTIL_H_
#define BESPOKE_TESTS_SUPPORT_BATCH_TEST_UTIL_H_

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/batch/process.h"
#include "tests/support/run_command.h"  // ReadText

namespace bespoke::testing {

// Paths baked in by CMake.
std::filesystem::path BespokeBinary();
std::filesystem::path FakeWorkerBinary();

// Starts `bespoke args...` with output to `log`; returns its pid.
pid_t StartBespoke(const std::vector<std::string>& args, const std::filesystem::path& log);
// Runs it to the end; returns the exit code (or 128 + signal).
int RunBespoke(const std::vector<std::string>& args, const std::filesystem::path& log);

void WriteText(const std::filesystem::path& file, const std::string& text);

// Scan folders under `out_dir` holding a done.json.
int CountDone(const std::filesystem::path& out_dir);

// Data lines of a CSV (header excluded).
std::vector<std::string> CsvRows(const std::string& csv);

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_BATCH_TEST_UTIL_H_
