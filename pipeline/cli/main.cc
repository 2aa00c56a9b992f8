// `bespoke <command> ...`: the only place that turns errors into exit codes.
//   0 ok, 1 bad input (InputError, bad options), 2 internal error.
#include <malloc.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <map>
#include <new>
#include <string>

#include "pipeline/cli/commands.h"
#include "scanners/core/errors.h"

namespace {

// Every stage allocates and frees arrays of megabytes to tens of megabytes
// (clouds, indices, grids, geodesic windows). By default glibc hands such
// blocks back to the kernel on free, and the next stage faults fresh pages in
// again: page faults were the largest kernel cost of a measure run under
// perf on a 2-core VM (525k-point scan, docs/measuring.md). Kept in the heap,
// the blocks are reused.
void KeepFreedMemory() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // blocks up to 32 MB (glibc's limit) from the heap
  mallopt(M_TRIM_THRESHOLD, 1 << 30);   // the heap's top is given back beyond 1 GB free
}

void ConfigureLogging(const bespoke::GlobalOptions& global) {
  auto logger = spdlog::stderr_color_mt("bespoke");
  logger->set_pattern("%^%l%$: %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(global.quiet ? spdlog::level::warn
                                 : (global.verbose ? spdlog::level::debug : spdlog::level::info));
}

int Run(int argc, char** argv) {
  CLI::App app{
      "bespoke: a 3-D body scan in, tailoring measurements and a fitted sewing pattern out."};
  app.require_subcommand(1);
  app.fallthrough();
  bespoke::GlobalOptions global;
  app.add_flag("-q,--quiet", global.quiet, "Only warnings and errors; no progress bar");
  app.add_flag("-v,--verbose", global.verbose, "Debug output");

  std::map<const CLI::App*, bespoke::CommandRunner> runners;
  for (const bespoke::Command& command : bespoke::AllCommands()) {
    CLI::App* sub = app.add_subcommand(command.name, command.summary);
    runners[sub] = command.setup(*sub);
  }
  // The first word that is not a global flag names the subcommand: say so when
  // it is none of them (CLI11 alone would only say that one is required).
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (!word.empty() && word[0] == '-') continue;
    bool known = false;
    for (const bespoke::Command& command : bespoke::AllCommands())
      known = known || word == command.name;
    if (!known) {
      std::fprintf(stderr, "bespoke: unknown command '%s' (bespoke --help lists the commands)\n",
                   word.c_str());
      return 1;
    }
    break;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help or the parse error
    return code == 0 ? 0 : 1;
  }
  ConfigureLogging(global);
  for (const CLI::App* sub : app.get_subcommands()) return runners.at(sub)(global);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  KeepFreedMemory();
  try {
    return Run(argc, argv);
  } catch (const bespoke::InputError& e) {
    spdlog::error("{}", e.what());
    return 1;
  } catch (const bespoke::InternalError& e) {
    spdlog::critical("internal error: {}", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    spdlog::critical("internal error: out of memory");
    return 2;
  } catch (const std::exception& e) {
    spdlog::critical("internal error: {}", e.what());
    return 2;
  }
}
