#include "pipeline/cli/progress_bar.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>

namespace bespoke {
namespace {

std::string FormatSeconds(double s) {
  if (s < 0 || s > 1e7) return "?";
  const int total = static_cast<int>(s + 0.5);
  char buffer[32];
  if (total >= 3600) {
    std::snprintf(buffer, sizeof buffer, "%dh%02dm", total / 3600, (total / 60) % 60);
  } else {
    std::snprintf(buffer, sizeof buffer, "%dm%02ds", total / 60, total % 60);
  }
  return buffer;
}

}  // namespace

ProgressBar::ProgressBar(bool quiet) : quiet_(quiet), tty_(::isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() {
  if (active_) End();
}

void ProgressBar::Begin(std::string_view stage, std::int64_t total) {
  if (active_) End();
  stage_ = std::string(stage);
  total_ = total;
  done_ = 0;
  last_logged_decile_ = -1;
  start_ = last_draw_ = std::chrono::steady_clock::now();
  active_ = true;
  if (!quiet_ && !tty_)
    spdlog::info("{}: started{}", stage_, total_ > 0 ? fmt::format(" ({} steps)", total_) : "");
}

void ProgressBar::Update(std::int64_t done) {
  if (!active_ || quiet_) return;
  done_ = done;
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    if (now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    Draw(false);
  } else if (total_ > 0) {
    const int decile = static_cast<int>(10 * done_ / total_);
    if (decile > last_logged_decile_ && now - last_draw_ >= std::chrono::seconds(5)) {
      last_logged_decile_ = decile;
      last_draw_ = now;
      spdlog::info("{}: {}/{} ({}%)", stage_, done_, total_, 100 * done_ / total_);
    }
  }
}

void ProgressBar::End() {
  if (!active_) return;
  active_ = false;
  if (quiet_) return;
  if (tty_) {
    if (total_ > 0) done_ = total_;
    Draw(true);
  }
}

void ProgressBar::Draw(bool final) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? done_ / elapsed : 0.0;
  std::string line = "\r" + stage_ + " ";
  if (total_ > 0) {
    constexpr int kWidth = 30;
    const double fraction = std::min(1.0, static_cast<double>(done_) / total_);
    const int filled = static_cast<int>(fraction * kWidth);
    line += "[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] ";
    line += fmt::format("{}/{} {:.1f}/s ", done_, total_, rate);
    line += final ? "in " + FormatSeconds(elapsed)
                  : "ETA " + FormatSeconds(rate > 0 ? (total_ - done_) / rate : -1);
  } else {
    line += fmt::format("{} done {:.1f}/s {}", done_, rate, FormatSeconds(elapsed));
  }
  std::fprintf(stderr, "%s\033[K%s", line.c_str(), final ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace bespoke
