#include "pipeline/commands.h"

#include <CLI/CLI.hpp>

namespace bespoke {

// One declaration and one table row per subcommand (pipeline/cmd_<name>.cc).
CommandRunner SetupVersionCommand(CLI::App& app);

const std::vector<Command>& AllCommands() {
  static const std::vector<Command> commands = {
      {"version", "Print the version and the libraries Bespoke was built with",
       &SetupVersionCommand},
  };
  return commands;
}

}  // namespace bespoke
