#include "tests/support/run_command.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace bespoke::testing {

std::string Quote(const std::filesystem::path& path) {
  std::string quoted = "'";
  for (const char c : path.string()) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

CommandResult RunCommand(const std::string& command_line,
                         const std::filesystem::path& scratch_dir) {
  const std::filesystem::path out = scratch_dir / "command-stdout.txt";
  const std::filesystem::path err = scratch_dir / "command-stderr.txt";
  const std::string command = command_line + " > " + Quote(out) + " 2> " + Quote(err);
  const int status = std::system(command.c_str());
  CommandResult result;
  if (status == -1) {
    result.exit_code = -1;
  } else if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.exit_code = 128 + WTERMSIG(status);
  }
  result.out = ReadText(out);
  result.err = ReadText(err);
  return result;
}

}  // namespace bespoke::testing
