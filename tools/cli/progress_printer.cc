#include "tools/cli/progress_printer.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace mlndt {
namespace tools {

ProgressPrinter::ProgressPrinter(std::string label,
                                 std::vector<std::string> item_names)
    : label_(std::move(label)),
      item_names_(std::move(item_names)),
      terminal_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

void ProgressPrinter::operator()(const ProgressEvent& event) {
  std::string detail = event.status;
  if (event.index < item_names_.size()) {
    detail = item_names_[event.index] + (detail.empty() ? "" : " " + detail);
  }
  const std::string times = Times(event.done, event.total);
  if (terminal_) {
    constexpr size_t kWidth = 30;
    const size_t filled =
        event.total > 0 ? std::min(kWidth, kWidth * event.done / event.total)
                        : 0;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr,
                 "\r\033[K%s [%s] %zu/%zu %s %s",
                 label_.c_str(),
                 bar.c_str(),
                 event.done,
                 event.total,
                 detail.c_str(),
                 times.c_str());
    open_line_ = true;
  } else {
    std::fprintf(stderr,
                 "%s %zu/%zu %s %s\n",
                 label_.c_str(),
                 event.done,
                 event.total,
                 detail.c_str(),
                 times.c_str());
  }
  std::fflush(stderr);
}

void ProgressPrinter::Finish() {
  if (open_line_) std::fprintf(stderr, "\n");
  open_line_ = false;
}

std::string ProgressPrinter::Times(size_t done, size_t total) const {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_)
          .count();
  char text[64];
  if (done > 0 && total >= done) {
    const double eta =
        elapsed / static_cast<double>(done) * static_cast<double>(total - done);
    std::snprintf(text, sizeof(text), "[%.0f s, ETA %.0f s]", elapsed, eta);
  } else {
    std::snprintf(text, sizeof(text), "[%.0f s]", elapsed);
  }
  return text;
}

}  // namespace tools
}  // namespace mlndt
