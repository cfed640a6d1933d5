#pragma once

// Progress on stderr for long tool runs: one bar with the elapsed time and
// an ETA, redrawn in place when stderr is a terminal, one plain line per
// step otherwise (logs, pipes, CI).

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace mlndt {

class Progress {
 public:
  // `label` prefixes every line; `total` steps are expected (0: unknown).
  Progress(std::string label, size_t total)
      : label_(std::move(label)),
        total_(total),
        terminal_(isatty(STDERR_FILENO) == 1),
        start_(std::chrono::steady_clock::now()) {}
  ~Progress() { Finish(); }

  // Reports that `done` steps are complete; `detail` describes the last one.
  void Update(size_t done, const std::string& detail) {
    const std::string times = Times(done);
    if (terminal_) {
      constexpr int kWidth = 30;
      const int filled =
          total_ > 0 ? static_cast<int>(kWidth * done / total_) : 0;
      std::string bar(static_cast<size_t>(filled), '#');
      bar.resize(kWidth, '.');
      std::fprintf(stderr,
                   "\r\033[K%s [%s] %zu/%zu %s %s",
                   label_.c_str(),
                   bar.c_str(),
                   done,
                   total_,
                   detail.c_str(),
                   times.c_str());
      open_line_ = true;
    } else {
      std::fprintf(stderr,
                   "%s %zu/%zu %s %s\n",
                   label_.c_str(),
                   done,
                   total_,
                   detail.c_str(),
                   times.c_str());
    }
    std::fflush(stderr);
  }

  // Ends the bar's line (idempotent).
  void Finish() {
    if (open_line_) std::fprintf(stderr, "\n");
    open_line_ = false;
  }

 private:
  // "[12 s, ETA 30 s]": the elapsed time and the rest at the mean pace.
  std::string Times(size_t done) const {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_)
            .count();
    char text[64];
    if (done > 0 && total_ >= done) {
      const double eta = elapsed / static_cast<double>(done) *
                         static_cast<double>(total_ - done);
      std::snprintf(text, sizeof(text), "[%.0f s, ETA %.0f s]", elapsed, eta);
    } else {
      std::snprintf(text, sizeof(text), "[%.0f s]", elapsed);
    }
    return text;
  }

  std::string label_;
  size_t total_ = 0;
  bool terminal_ = false;
  bool open_line_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace mlndt
