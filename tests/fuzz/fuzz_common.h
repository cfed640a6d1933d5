#pragma once

// Shared by the libFuzzer targets in tests/fuzz/ (one per reader; built only
// with -DMLNDT_BUILD_FUZZERS=ON and clang, run by .ci/fuzz). Besides "no
// crash, no leak, no undefined behaviour, bounded memory and time", the
// targets check invariants and abort when one breaks, so that a silently
// wrong result is a finding too.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/cloud/point_cloud.h"

// Aborts (a crash for libFuzzer, with the input saved) when `condition` is
// false.
#define MLNDT_FUZZ_CHECK(condition)                  \
  do {                                               \
    if (!(condition)) {                              \
      std::fprintf(stderr,                           \
                   "invariant failed: %s (%s:%d)\n", \
                   #condition,                       \
                   __FILE__,                         \
                   __LINE__);                        \
      std::abort();                                  \
    }                                                \
  } while (false)

namespace mlndt {
namespace fuzz {

// A scratch file of this process for the readers that take a path: in
// $MLNDT_FUZZ_TMPDIR, else /dev/shm (no disk I/O), else /tmp.
inline std::string ScratchPath(const std::string& name) {
  const char* folder = std::getenv("MLNDT_FUZZ_TMPDIR");
  std::string dir = folder != nullptr ? folder : "";
  if (dir.empty()) dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  return dir + "/mlndt_fuzz_" + std::to_string(getpid()) + "_" + name;
}

// Writes the fuzz input to `path` (aborts when that fails: not a finding).
inline void WriteScratch(const std::string& path, const std::string& bytes) {
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr ||
      std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size() ||
      std::fclose(file) != 0) {
    std::perror(path.c_str());
    std::abort();
  }
}

// Replaces the first line that starts with `keyword` by `line`, so that a
// target's input always reaches the body parser it is for while the rest of
// the header stays fuzzed. Inputs without such a line are left alone.
inline std::string ForceLine(const std::string& text,
                             const std::string& keyword,
                             const std::string& line) {
  size_t begin = 0;
  while (begin < text.size()) {
    const size_t end = text.find('\n', begin);
    const size_t stop = end == std::string::npos ? text.size() : end;
    if (text.compare(begin, keyword.size(), keyword) == 0) {
      return text.substr(0, begin) + line + text.substr(stop);
    }
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return text;
}

// What ReadPointCloud keeps of a parse: the finite points.
inline PointCloud FinitePoints(const std::vector<Eigen::Vector3d>& points) {
  PointCloud cloud(points);
  RemoveNonFinite(&cloud);
  return cloud;
}

// A parsed cloud written as PCD binary and as PLY binary and parsed again
// gives back its points rounded to float32 (the writers' precision).
inline void CheckWriteReadRoundTrip(const PointCloud& cloud) {
  for (int format = 0; format < 2; ++format) {
    const std::string bytes = format == 0 ? internal::EncodePcdBinary(cloud)
                                          : internal::EncodePlyBinary(cloud);
    std::vector<Eigen::Vector3d> again;
    std::string error;
    const bool ok = format == 0 ? internal::ParsePcd(bytes, &again, &error)
                                : internal::ParsePly(bytes, &again, &error);
    if (!ok) std::fprintf(stderr, "re-read failed: %s\n", error.c_str());
    MLNDT_FUZZ_CHECK(ok);
    MLNDT_FUZZ_CHECK(again.size() == cloud.size());
    for (size_t i = 0; i < again.size(); ++i) {
      for (int a = 0; a < 3; ++a) {
        const double expected = static_cast<float>(cloud[i](a));
        MLNDT_FUZZ_CHECK(again[i](a) == expected);
      }
    }
  }
}

// The common body of the cloud targets: parse, and on success check that
// the writers reproduce what was read.
template <typename Parser>
int FuzzCloudParser(Parser parse, const std::string& data) {
  std::vector<Eigen::Vector3d> points;
  std::string error;
  if (!parse(data, &points, &error)) {
    MLNDT_FUZZ_CHECK(!error.empty());  // Every failure says why.
    return 0;
  }
  CheckWriteReadRoundTrip(FinitePoints(points));
  return 0;
}

}  // namespace fuzz
}  // namespace mlndt
