#pragma once

// A real, tiny file system for "disk full" tests: a tmpfs of a given size
// mounted on a fresh folder. Needs root (CAP_SYS_ADMIN). The mount goes into
// a private mount namespace of the test process when the kernel allows it
// (unshare(CLONE_NEWNS)), so nobody else sees it and it disappears with the
// process; otherwise it is mounted normally and lazily unmounted by the
// destructor.
//
// Tests call Mount(); when it fails they GTEST_SKIP() with the reason,
// unless MLNDT_REQUIRE_SMALL_FS=1 is set (CI runs as root and sets it, so the
// test fails there instead of skipping silently).

#include <gtest/gtest.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace mlndt {
namespace testing {

class SmallFileSystem {
 public:
  SmallFileSystem() = default;
  SmallFileSystem(const SmallFileSystem&) = delete;
  SmallFileSystem& operator=(const SmallFileSystem&) = delete;
  ~SmallFileSystem() {
    if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
    if (!path_.empty()) ::rmdir(path_.c_str());
  }

  // Mounts a tmpfs of `bytes` (rounded up to pages by the kernel). False
  // with *reason when this process cannot.
  bool Mount(size_t bytes, std::string* reason) {
    std::string pattern = ::testing::TempDir() + "mlndt_small_fs_XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
      *reason = "mkdtemp failed: " + std::string(std::strerror(errno));
      return false;
    }
    path_ = pattern;
    if (::geteuid() != 0) {
      *reason = "mounting a small tmpfs needs root (euid is " +
                std::to_string(::geteuid()) + ")";
      return false;
    }
    // A private namespace keeps the mount to ourselves; not fatal if the
    // kernel or a multi-threaded process refuses.
    if (::unshare(CLONE_NEWNS) == 0) {
      ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr);
    }
    const std::string options = "size=" + std::to_string(bytes) + ",mode=0755";
    if (::mount("tmpfs", path_.c_str(), "tmpfs", 0, options.c_str()) != 0) {
      *reason = "mount -t tmpfs -o " + options + " " + path_ +
                " failed: " + std::strerror(errno);
      return false;
    }
    mounted_ = true;
    return true;
  }

  const std::string& path() const { return path_; }

  // Fills the file system with the file "filler" until a write fails, so
  // that not even one more block is free. Returns the bytes written.
  size_t Fill() {
    const std::string filler = path_ + "/filler";
    FILE* file = std::fopen(filler.c_str(), "wb");
    if (file == nullptr) return 0;
    std::setvbuf(file, nullptr, _IONBF, 0);
    const std::string block(512, 'f');
    size_t written = 0;
    while (true) {
      const size_t n = std::fwrite(block.data(), 1, block.size(), file);
      written += n;
      if (n < block.size()) break;
    }
    std::fclose(file);
    return written;
  }

  // Free bytes for an unprivileged writer (tmpfs: the same as for root).
  size_t FreeBytes() const {
    struct statvfs info;
    if (::statvfs(path_.c_str(), &info) != 0) return 0;
    return static_cast<size_t>(info.f_bavail) * info.f_frsize;
  }

 private:
  std::string path_;
  bool mounted_ = false;
};

// True when a test must fail rather than skip without a small file system.
inline bool SmallFileSystemRequired() {
  const char* value = std::getenv("MLNDT_REQUIRE_SMALL_FS");
  return value != nullptr && std::string(value) == "1";
}

}  // namespace testing
}  // namespace mlndt

// Mounts `fs` with `bytes` or skips the test (fails it when required).
#define MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, bytes)                         \
  do {                                                                  \
    std::string mlndt_small_fs_reason;                                  \
    if (!(fs).Mount((bytes), &mlndt_small_fs_reason)) {                 \
      if (::mlndt::testing::SmallFileSystemRequired()) {                \
        FAIL() << "MLNDT_REQUIRE_SMALL_FS=1 but no small file system: " \
               << mlndt_small_fs_reason;                                \
      }                                                                 \
      GTEST_SKIP() << "no small file system for the disk-full test: "   \
                   << mlndt_small_fs_reason;                            \
    }                                                                   \
  } while (false)
