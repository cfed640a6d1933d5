#include "lab/bench/bench_child.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mlndt {
namespace {

// BenchEstimate's fields as plain numbers (what crosses the pipe).
struct EstimateMessage {
  double pose[16];
  double covariance[36];
  double time_ms, align_ms, score;
  int64_t point_iterations;
  int32_t iterations;
  char usable, converged;
};

EstimateMessage ToMessage(const BenchEstimate& e) {
  EstimateMessage m{};
  Eigen::Map<Eigen::Matrix4d>(m.pose) = e.reference_from_input.matrix();
  Eigen::Map<Matrix6d>(m.covariance) = e.covariance;
  m.time_ms = e.time_ms;
  m.align_ms = e.align_ms;
  m.score = e.score;
  m.point_iterations = e.point_iterations;
  m.iterations = e.iterations;
  m.usable = e.usable;
  m.converged = e.converged;
  return m;
}

BenchEstimate FromMessage(const EstimateMessage& m) {
  BenchEstimate e;
  e.reference_from_input.matrix() = Eigen::Map<const Eigen::Matrix4d>(m.pose);
  e.covariance = Eigen::Map<const Matrix6d>(m.covariance);
  e.time_ms = m.time_ms;
  e.align_ms = m.align_ms;
  e.score = m.score;
  e.point_iterations = m.point_iterations;
  e.iterations = m.iterations;
  e.usable = m.usable != 0;
  e.converged = m.converged != 0;
  return e;
}

// Reads exactly `size` bytes; false on end of file or error.
bool ReadAll(int fd, char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

bool RunInChildProcess(const std::function<BenchEstimate()>& run,
                       BenchEstimate* estimate,
                       std::string* error) {
  int fds[2];
  if (pipe(fds) != 0) {
    *error = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    *error = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  if (pid == 0) {
    close(fds[0]);
    const EstimateMessage m = ToMessage(run());
    const char* data = reinterpret_cast<const char*>(&m);
    size_t left = sizeof(m);
    while (left > 0) {
      const ssize_t n = write(fds[1], data, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) _exit(1);
      data += n;
      left -= static_cast<size_t>(n);
    }
    _exit(0);  // No destructors or atexit handlers of the parent's state.
  }
  close(fds[1]);
  EstimateMessage m;
  const bool received = ReadAll(fds[0], reinterpret_cast<char*>(&m), sizeof(m));
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!received || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    *error = "the one-shot child process died before it reported";
    return false;
  }
  *estimate = FromMessage(m);
  return true;
}

}  // namespace mlndt
