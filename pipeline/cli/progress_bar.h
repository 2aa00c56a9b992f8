// The CLI's Progress: a bar with count, rate and ETA on a terminal; plain log
// lines (every 10 %, at most one per 5 s) when stderr is not a terminal; nothing
// with --quiet.
#ifndef BESPOKE_PIPELINE_CLI_PROGRESS_BAR_H_
#define BESPOKE_PIPELINE_CLI_PROGRESS_BAR_H_

#include <chrono>
#include <cstdint>
#include <string>

#include "scanners/core/progress.h"

namespace bespoke {

class ProgressBar : public Progress {
 public:
  // quiet: report nothing. Otherwise draws on stderr if it is a terminal.
  explicit ProgressBar(bool quiet);
  ~ProgressBar() override;

  void Begin(std::string_view stage, std::int64_t total) override;
  void Update(std::int64_t done) override;
  void End() override;

 private:
  void Draw(bool final);

  bool quiet_;
  bool tty_;
  std::string stage_;
  std::int64_t total_ = 0;
  std::int64_t done_ = 0;
  int last_logged_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool active_ = false;
};

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_CLI_PROGRESS_BAR_H_
