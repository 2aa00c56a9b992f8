// `bespoke version`: the version and the library versions it was built with.
#include <CLI/CLI.hpp>
#include <iostream>

#include "pipeline/cli/commands.h"
#include "scanners/core/build_info.h"

namespace bespoke {

CommandRunner SetupVersionCommand(CLI::App& /*app*/) {
  return [](const GlobalOptions&) {
    std::cout << BuildInfoText();
    return 0;
  };
}

}  // namespace bespoke
