#include "mlndt/common/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <glog/logging.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <thread>

namespace mlndt {
namespace {

std::string ErrnoText(int error_number) { return std::strerror(error_number); }

// Splits `path` into its folder ("." when it has none) and its last
// component (empty when `path` ends with '/').
void SplitPath(const std::string& path,
               std::string* folder,
               std::string* name) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) {
    *folder = ".";
    *name = path;
  } else {
    *folder = slash == 0 ? "/" : path.substr(0, slash);
    *name = path.substr(slash + 1);
  }
}

// What lstat says about `path`: *exists and, for an existing regular file,
// its permission bits. False with *error for anything that is not a regular
// file or a missing one.
bool InspectTarget(const std::string& path,
                   bool* exists,
                   mode_t* mode,
                   std::string* error) {
  *exists = false;
  *mode = 0;
  struct stat status;
  if (::lstat(path.c_str(), &status) != 0) {
    if (errno == ENOENT) return true;
    *error = path + ": cannot write: " + ErrnoText(errno);
    return false;
  }
  const char* kind = nullptr;
  if (S_ISLNK(status.st_mode)) {
    kind = "it is a symbolic link (refusing to write through or replace it)";
  } else if (S_ISDIR(status.st_mode)) {
    kind = "it is a directory";
  } else if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) {
    kind = "it is a device node (refusing to write to or replace it)";
  } else if (S_ISFIFO(status.st_mode)) {
    kind = "it is a FIFO (refusing to write to or replace it)";
  } else if (S_ISSOCK(status.st_mode)) {
    kind = "it is a socket (refusing to replace it)";
  } else if (!S_ISREG(status.st_mode)) {
    kind = "it is not a regular file";
  }
  if (kind != nullptr) {
    *error = path + ": cannot write: " + kind;
    return false;
  }
  *exists = true;
  *mode = status.st_mode & 07777;
  return true;
}

// Six random characters for a temporary name. The generator is per thread
// and seeded from the random device, the thread and the clock, so threads
// and processes draw different sequences (a clash only costs a retry).
constexpr char kAlphabet[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
constexpr size_t kSuffixLength = 6;

std::string RandomSuffix() {
  thread_local std::mt19937_64 generator([] {
    std::random_device device;
    const uint64_t clock = static_cast<uint64_t>(
        std::chrono::steady_clock::now().time_since_epoch().count());
    std::seed_seq seed{static_cast<uint64_t>(device()),
                       static_cast<uint64_t>(device()),
                       static_cast<uint64_t>(::getpid()),
                       static_cast<uint64_t>(std::hash<std::thread::id>()(
                           std::this_thread::get_id())),
                       clock};
    return std::mt19937_64(seed);
  }());
  std::string suffix(kSuffixLength, 'X');
  for (char& c : suffix) c = kAlphabet[generator() % (sizeof(kAlphabet) - 1)];
  return suffix;
}

// True for "<prefix>XXXXXX": a temporary file name of the same target.
bool IsTemporaryName(const std::string& entry, const std::string& prefix) {
  if (entry.size() != prefix.size() + kSuffixLength ||
      entry.compare(0, prefix.size(), prefix) != 0) {
    return false;
  }
  const std::string alphabet = kAlphabet;
  return entry.find_first_not_of(alphabet, prefix.size()) == std::string::npos;
}

// Removes the temporary files "<prefix>XXXXXX" in `folder` that no writer
// holds: a live writer keeps an exclusive flock on its temporary file until
// the rename, the kernel drops the lock of a killed one. Best effort: what
// cannot be opened, locked or removed stays.
void RemoveStaleTemporaries(const std::string& folder,
                            const std::string& prefix) {
  DIR* dir = ::opendir(folder.c_str());
  if (dir == nullptr) return;
  const int dir_fd = ::dirfd(dir);
  while (const dirent* entry = ::readdir(dir)) {
    if (!IsTemporaryName(entry->d_name, prefix)) continue;
    const int fd = ::openat(
        dir_fd, entry->d_name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat opened, named;
    if (::fstat(fd, &opened) == 0 && S_ISREG(opened.st_mode) &&
        ::flock(fd, LOCK_EX | LOCK_NB) == 0 &&
        ::fstatat(dir_fd, entry->d_name, &named, AT_SYMLINK_NOFOLLOW) == 0 &&
        named.st_dev == opened.st_dev && named.st_ino == opened.st_ino) {
      ::unlinkat(dir_fd, entry->d_name, 0);
    }
    ::close(fd);
  }
  ::closedir(dir);
}

// Locks our new temporary file `fd` (see RemoveStaleTemporaries). False
// when a cleaner removed it before we held the lock: try another name.
bool LockTemporary(int fd, const std::string& temporary) {
  if (::flock(fd, LOCK_EX) != 0) return true;  // No locks here: no cleaner.
  struct stat opened, named;
  return ::fstat(fd, &opened) == 0 && ::lstat(temporary.c_str(), &named) == 0 &&
         named.st_dev == opened.st_dev && named.st_ino == opened.st_ino;
}

// Creates and locks a new temporary file ".<name>.tmp.XXXXXX" in `folder`
// (mkstemp's O_EXCL + random name, but with mode 0644 through the umask
// instead of mkstemp's 0600), after removing the stale ones. Returns its
// descriptor, or -1 with *open_errno.
int CreateTemporary(const std::string& folder,
                    const std::string& name,
                    std::string* temporary,
                    int* open_errno) {
  const std::string temporary_name = "." + name + ".tmp.";
  RemoveStaleTemporaries(folder, temporary_name);
  const std::string prefix =
      (folder == "/" ? "/" : folder + "/") + temporary_name;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    *temporary = prefix + RandomSuffix();
    fd = ::open(temporary->c_str(),
                O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW,
                0644);
    *open_errno = errno;
    if (fd < 0 && *open_errno != EEXIST) break;
    if (fd >= 0 && !LockTemporary(fd, *temporary)) {
      ::close(fd);
      fd = -1;
      *open_errno = EEXIST;
    }
  }
  return fd;
}

// Writes all of `bytes`, resuming short writes. Returns 0 or an errno.
int WriteAll(int fd, std::string_view bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n =
        ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;  // Never happens for regular files.
    written += static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

bool CheckWritableFilePath(const std::string& path, std::string* error) {
  CHECK(error != nullptr);
  std::string folder, name;
  SplitPath(path, &folder, &name);
  if (name.empty()) {
    *error = path + ": cannot write: the path names a directory";
    return false;
  }
  bool exists = false;
  mode_t mode = 0;
  if (!InspectTarget(path, &exists, &mode, error)) return false;
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    *error =
        path + ": cannot write in folder " + folder + ": " + ErrnoText(errno);
    return false;
  }
  return true;
}

bool WriteFileAtomically(const std::string& path,
                         std::string_view bytes,
                         std::string* error) {
  CHECK(error != nullptr);
  std::string folder, name;
  SplitPath(path, &folder, &name);
  if (name.empty()) {
    *error = path + ": cannot write: the path names a directory";
    return false;
  }
  bool exists = false;
  mode_t mode = 0;
  if (!InspectTarget(path, &exists, &mode, error)) return false;

  // Step 2: our own temporary file, locked.
  std::string temporary;
  int open_errno = 0;
  const int fd = CreateTemporary(folder, name, &temporary, &open_errno);
  if (fd < 0) {
    *error = path + ": cannot create a temporary file in " + folder + ": " +
             ErrnoText(open_errno);
    return false;
  }

  // The lock lives as long as the open file description: this duplicate
  // keeps it held past close(fd) until the rename is done.
  const int lock_fd = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);

  // Step 3: contents, mode, fsync, close; each one checked.
  const char* failed_step = nullptr;
  int failure = WriteAll(fd, bytes);
  if (failure != 0) failed_step = "write failed";
  if (failure == 0 && exists && ::fchmod(fd, mode) != 0) {
    failure = errno;
    failed_step = "cannot set the file mode";
  }
  if (failure == 0 && ::fsync(fd) != 0) {
    failure = errno;
    failed_step = "fsync failed";
  }
  if (::close(fd) != 0 && failure == 0) {
    failure = errno;
    failed_step = "close failed";
  }
  if (failure == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) {
    failure = errno;
    failed_step = "cannot rename the temporary file onto it";
  }
  if (failure != 0) ::unlink(temporary.c_str());
  if (lock_fd >= 0) ::close(lock_fd);
  if (failure != 0) {
    *error = path + ": " + failed_step + ": " + ErrnoText(failure) +
             " (nothing written; the previous file, if any, is unchanged)";
    return false;
  }

  // The rename is durable once the folder is synced. EINVAL: the file
  // system cannot sync folders (the rename still happened).
  const int folder_fd =
      ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  int folder_failure = folder_fd < 0 ? errno : 0;
  if (folder_fd >= 0) {
    if (::fsync(folder_fd) != 0 && errno != EINVAL) folder_failure = errno;
    ::close(folder_fd);
  }
  if (folder_failure != 0) {
    *error = path + ": written, but cannot fsync its folder " + folder + ": " +
             ErrnoText(folder_failure) +
             " (the new contents are in place but may not survive a crash)";
    return false;
  }
  return true;
}

}  // namespace mlndt
