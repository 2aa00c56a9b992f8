// The `bespoke` command line is a dispatch table of subcommands.
//
// Each subcommand lives in pipeline/cmd_<name>.cc and provides a setup
// function that declares its options on a CLI11 subcommand, bound to an
// options struct it owns, and returns the runner. The runner checks the
// options (options.Check()), calls the library, writes its outputs (atomic)
// and the settings it used, and returns the exit code. Errors are thrown as
// bespoke::InputError / InternalError; main() maps them to exit codes
//   0 ok, 1 bad input, 2 internal error.
#ifndef BESPOKE_PIPELINE_CLI_COMMANDS_H_
#define BESPOKE_PIPELINE_CLI_COMMANDS_H_

#include <functional>
#include <vector>

namespace CLI {
class App;
}

namespace bespoke {

// Options every subcommand shares (given before or after the subcommand name).
struct GlobalOptions {
  bool quiet = false;    // --quiet: warnings and errors only, no progress bar
  bool verbose = false;  // --verbose: debug log lines
};

using CommandRunner = std::function<int(const GlobalOptions&)>;

struct Command {
  const char* name;     // "clean"
  const char* summary;  // one line for `bespoke --help`
  CommandRunner (*setup)(CLI::App& subcommand);
};

// Every subcommand, in the order `bespoke --help` lists them.
const std::vector<Command>& AllCommands();

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_CLI_COMMANDS_H_
