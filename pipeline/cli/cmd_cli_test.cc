// The `bespoke` command line as a whole, run as a process: `--help` lists every
// subcommand of the dispatch table and each subcommand has its own help; an
// unknown or missing subcommand is exit 1; long work shows a progress bar on a
// terminal (a pseudo-terminal from script(1)), plain log lines when stderr is
// not a terminal, and nothing with --quiet.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "pipeline/cli/commands.h"
#include "tests/support/draft_measurements.h"
#include "tests/support/run_command.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::Quote;
using testing::ReadText;
using testing::RunCommand;
using testing::TempDir;

std::string Binary() { return std::string("'") + BESPOKE_BINARY + "'"; }

TEST(Cli, HelpListsEveryCommandAndEachHasItsOwnHelp) {
  TempDir dir;
  const auto help = RunCommand(Binary() + " --help", dir.path());
  ASSERT_EQ(help.exit_code, 0) << help.err;
  ASSERT_GE(AllCommands().size(), 10u);
  for (const Command& c : AllCommands()) {
    EXPECT_THAT(help.out, HasSubstr(c.name)) << "bespoke --help does not list " << c.name;
    const auto sub = RunCommand(Binary() + " " + c.name + " --help", dir.path());
    EXPECT_EQ(sub.exit_code, 0) << c.name << ": " << sub.err;
    EXPECT_THAT(sub.out, HasSubstr("Usage")) << c.name;
    EXPECT_THAT(sub.out, HasSubstr(c.name)) << c.name;
  }
}

TEST(Cli, UnknownOrMissingCommandIsExitOne) {
  TempDir dir;
  EXPECT_EQ(RunCommand(Binary(), dir.path()).exit_code, 1);
  const auto unknown = RunCommand(Binary() + " measure-everything", dir.path());
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_THAT(unknown.err + unknown.out, HasSubstr("measure-everything"));
  EXPECT_EQ(RunCommand(Binary() + " info --no-such-flag x.ply", dir.path()).exit_code, 1);
}

// A small GA run (a few seconds) is the long work: `resize` reports its
// generations through the progress bar.
class CliProgress : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto draft = RunCommand(
        Binary() + " --quiet draft --design shirt -o " + Quote(dir_ / "draft"), dir_.path());
    ASSERT_EQ(draft.exit_code, 0) << draft.err;
    std::ofstream(dir_ / "body.json")
        << testing::ScaledDraftMeasurements(dir_ / "draft" / "draft.json", 1.05).dump();
  }
  std::string Resize(const std::string& global, const std::string& out) const {
    return Binary() + " " + global + " resize --design shirt --measurements " +
           Quote(dir_ / "body.json") + " --population 60 --generations 40 -o " + Quote(dir_ / out);
  }
  TempDir dir_;
};

TEST_F(CliProgress, BarOnATerminalLogLinesOtherwiseNothingWhenQuiet) {
  // script(1) gives the command a pseudo-terminal; its output is the terminal's.
  const auto tty =
      RunCommand("script -qec " + Quote(Resize("", "tty")) + " /dev/null", dir_.path());
  ASSERT_EQ(tty.exit_code, 0) << tty.out << tty.err;
  EXPECT_THAT(tty.out, HasSubstr("\revolving ["));
  EXPECT_THAT(tty.out, HasSubstr("40/40"));
  EXPECT_THAT(tty.out, HasSubstr("/s in "));  // rate and elapsed time on the final bar

  const auto plain = RunCommand(Resize("", "plain"), dir_.path());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_THAT(plain.err, HasSubstr("evolving: started (40 steps)"));
  EXPECT_THAT(plain.err, Not(HasSubstr("\r")));

  const auto quiet = RunCommand(Resize("--quiet", "quiet"), dir_.path());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_TRUE(std::filesystem::exists(dir_ / "quiet" / "fitted.json"));
}

}  // namespace
}  // namespace bespoke
