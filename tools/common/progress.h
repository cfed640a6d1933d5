#pragma once

// Progress on stderr for long tool runs: a bar redrawn in place when stderr
// is a terminal, one plain line per step otherwise (logs, pipes, CI).

#include <unistd.h>

#include <cstdio>
#include <string>

namespace mlndt {
namespace tools {

class Progress {
 public:
  // `label` prefixes every line; `total` steps are expected (0: unknown).
  Progress(std::string label, size_t total)
      : label_(std::move(label)),
        total_(total),
        terminal_(isatty(STDERR_FILENO) == 1) {}
  ~Progress() { Finish(); }

  // Reports that `done` steps are complete; `detail` describes the last one.
  void Update(size_t done, const std::string& detail) {
    if (terminal_) {
      constexpr int kWidth = 30;
      const int filled =
          total_ > 0 ? static_cast<int>(kWidth * done / total_) : 0;
      std::string bar(static_cast<size_t>(filled), '#');
      bar.resize(kWidth, '.');
      std::fprintf(stderr,
                   "\r\033[K%s [%s] %zu/%zu %s",
                   label_.c_str(),
                   bar.c_str(),
                   done,
                   total_,
                   detail.c_str());
      open_line_ = true;
    } else {
      std::fprintf(stderr,
                   "%s %zu/%zu %s\n",
                   label_.c_str(),
                   done,
                   total_,
                   detail.c_str());
    }
    std::fflush(stderr);
  }

  // Ends the bar's line (idempotent).
  void Finish() {
    if (open_line_) std::fprintf(stderr, "\n");
    open_line_ = false;
  }

 private:
  std::string label_;
  size_t total_ = 0;
  bool terminal_ = false;
  bool open_line_ = false;
};

}  // namespace tools
}  // namespace mlndt
