// Running the `bespoke` binary (or any command) as a user does, from
// process-level CLI tests: a shell command line, its exit code and its
// captured stdout and stderr.
//
//   CommandResult r = RunCommand(std::string(BESPOKE_BINARY) + " info " + Quote(file), dir);
//   EXPECT_EQ(r.exit_code, 1);
//   EXPECT_THAT(r.err, HasSubstr(file.string()));
//
// exit_code is the command's status, or 128 + signal number when a signal
// ended it (so a crash never looks like a clean exit 1). stdout/stderr are
// captured in files under `scratch_dir` (overwritten on each call).
#ifndef BESPOKE_TESTS_SUPPORT_RUN_COMMAND_H_
#define BESPOKE_TESTS_SUPPORT_RUN_COMMAND_H_

#include <filesystem>
#include <string>

namespace bespoke::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs `command_line` with /bin/sh; `scratch_dir` must exist.
CommandResult RunCommand(const std::string& command_line, const std::filesystem::path& scratch_dir);

// The path in single quotes for /bin/sh (single quotes inside escaped).
std::string Quote(const std::filesystem::path& path);

// A file's bytes; "" when it cannot be read.
std::string ReadText(const std::filesystem::path& file);

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_RUN_COMMAND_H_
