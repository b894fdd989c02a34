#pragma once
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace molsurf::cli {

// A progress bar per stage on stderr (percent and the stage's elapsed time), one line per
// stage, drawn when stderr is a terminal or --progress asks, never with -q. Redrawn at most
// ten times a second.
class ProgressBar {
 public:
  ProgressBar(bool quiet, bool force) : enabled_(!quiet && (force || isatty(STDERR_FILENO))) {}
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Ends the bar's last line; a later update starts a new one.
  void finish() {
    if (line_open_) std::fputc('\n', stderr);
    line_open_ = false;
    stage_ = nullptr;
  }

  void update(const char* stage, std::size_t done, std::size_t total) {
    if (!enabled_ || total == 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (stage != stage_) {
      if (line_open_) std::fputc('\n', stderr);
      stage_ = stage;
      stage_start_ = now;
      drawn_ = {};
    }
    if (done < total && drawn_ != std::chrono::steady_clock::time_point{} &&
        now - drawn_ < std::chrono::milliseconds(100))
      return;
    drawn_ = now;
    const int width = 30, filled = static_cast<int>(width * done / total);
    std::fprintf(stderr, "\r%-8s [%s%s] %3d%% %7.1f s", stage, std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), static_cast<int>(100 * done / total),
                 std::chrono::duration<double>(now - stage_start_).count());
    std::fflush(stderr);
    line_open_ = true;
  }

 private:
  bool enabled_;
  bool line_open_ = false;
  const char* stage_ = nullptr;
  std::chrono::steady_clock::time_point stage_start_, drawn_;
};

}  // namespace molsurf::cli
