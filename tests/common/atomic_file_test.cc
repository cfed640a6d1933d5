#include "mlndt/common/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/testing/small_file_system.h"

namespace mlndt {
namespace {

// A fresh, empty folder for the current test.
std::string FreshFolder() {
  const ::testing::TestInfo* test =
      ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string path = ::testing::TempDir() + "mlndt_atomic_file_test_" +
                           test->name() + "_" + std::to_string(::getpid());
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

std::string ReadBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << file.rdbuf();
  return buffer.str();
}

std::vector<std::string> FolderEntries(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

mode_t FileMode(const std::string& path) {
  struct stat status;
  EXPECT_EQ(::stat(path.c_str(), &status), 0) << path;
  return status.st_mode & 07777;
}

mode_t CurrentUmask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

::testing::AssertionResult Contains(const std::string& text,
                                    const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "'" << text << "' does not contain '" << part << "'";
}

TEST(WriteFileAtomically, NewFileGetsTheBytesAnd0644MinusUmask) {
  const std::string folder = FreshFolder();
  const std::string path = folder + "/out.json";
  const std::string bytes("{\"a\": 1}\n\0binary", 17);
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path, bytes, &error)) << error;
  EXPECT_EQ(ReadBytes(path), bytes);
  EXPECT_EQ(FileMode(path), 0644 & ~CurrentUmask());
  EXPECT_EQ(FolderEntries(folder), std::vector<std::string>{"out.json"});
}

TEST(WriteFileAtomically, EmptyContentsAndRelativePaths) {
  const std::string folder = FreshFolder();
  const std::string old_cwd = std::filesystem::current_path();
  std::filesystem::current_path(folder);
  std::string error;
  EXPECT_TRUE(WriteFileAtomically("empty.txt", "", &error)) << error;
  std::filesystem::current_path(old_cwd);
  EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/empty.txt"));
  EXPECT_EQ(std::filesystem::file_size(folder + "/empty.txt"), 0u);
  EXPECT_EQ(FolderEntries(folder), std::vector<std::string>{"empty.txt"});
}

TEST(WriteFileAtomically, ReplacingKeepsTheTargetMode) {
  const std::string folder = FreshFolder();
  const std::string path = folder + "/secret.csv";
  std::ofstream(path) << "old";
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path, "new", &error)) << error;
  EXPECT_EQ(ReadBytes(path), "new");
  EXPECT_EQ(FileMode(path), 0640u);
  ASSERT_EQ(::chmod(path.c_str(), 0755), 0);
  ASSERT_TRUE(WriteFileAtomically(path, "newer", &error)) << error;
  EXPECT_EQ(FileMode(path), 0755u);
}

TEST(WriteFileAtomically, RefusesSymlinksDirectoriesFifosAndDevices) {
  const std::string folder = FreshFolder();
  const std::string victim = folder + "/victim";
  std::ofstream(victim) << "victim";
  const std::string link = folder + "/link";
  ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
  const std::string dangling = folder + "/dangling";
  ASSERT_EQ(::symlink((folder + "/nowhere").c_str(), dangling.c_str()), 0);
  const std::string directory = folder + "/directory";
  std::filesystem::create_directories(directory);
  const std::string fifo = folder + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const std::string device = folder + "/null";
  const bool have_device =
      ::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;

  struct Case {
    std::string path;
    std::string keyword;
  };
  std::vector<Case> cases = {{link, "symbolic link"},
                             {dangling, "symbolic link"},
                             {directory, "directory"},
                             {directory + "/", "directory"},
                             {fifo, "FIFO"}};
  if (have_device) cases.push_back({device, "device node"});
  for (const Case& c : cases) {
    std::string error;
    EXPECT_FALSE(WriteFileAtomically(c.path, "data", &error)) << c.path;
    EXPECT_TRUE(Contains(error, c.path));
    EXPECT_TRUE(Contains(error, c.keyword));
    EXPECT_FALSE(CheckWritableFilePath(c.path, &error)) << c.path;
    EXPECT_TRUE(Contains(error, c.keyword));
  }
  EXPECT_EQ(ReadBytes(victim), "victim");
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_TRUE(std::filesystem::is_symlink(dangling));
  EXPECT_FALSE(std::filesystem::exists(folder + "/nowhere"));
  EXPECT_TRUE(std::filesystem::is_directory(directory));
  EXPECT_TRUE(std::filesystem::is_empty(directory));
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  if (have_device) EXPECT_TRUE(std::filesystem::is_character_file(device));
  std::vector<std::string> expected = {
      "dangling", "directory", "fifo", "link", "victim"};
  if (have_device) expected.push_back("null");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(FolderEntries(folder), expected);
}

TEST(WriteFileAtomically, MissingFolderNamesThePathAndTheReason) {
  const std::string path = FreshFolder() + "/no/such/folder/out.csv";
  std::string error;
  EXPECT_FALSE(WriteFileAtomically(path, "x", &error));
  EXPECT_TRUE(Contains(error, path));
  EXPECT_TRUE(Contains(error, std::strerror(ENOENT)));
  EXPECT_FALSE(CheckWritableFilePath(path, &error));
  EXPECT_TRUE(Contains(error, std::strerror(ENOENT)));
}

TEST(WriteFileAtomically, UnwritableFolderFailsWithPermissionDenied) {
  if (::geteuid() == 0) {
    GTEST_SKIP() << "root may write into a read-only folder";
  }
  const std::string folder = FreshFolder();
  ASSERT_EQ(::chmod(folder.c_str(), 0555), 0);
  std::string error;
  EXPECT_FALSE(WriteFileAtomically(folder + "/out", "x", &error));
  EXPECT_TRUE(Contains(error, std::strerror(EACCES)));
  ::chmod(folder.c_str(), 0755);
}

TEST(CheckWritableFilePath, AcceptsNewAndRegularFiles) {
  const std::string folder = FreshFolder();
  std::string error;
  EXPECT_TRUE(CheckWritableFilePath(folder + "/new.csv", &error)) << error;
  std::ofstream(folder + "/old.csv") << "old";
  EXPECT_TRUE(CheckWritableFilePath(folder + "/old.csv", &error)) << error;
  EXPECT_EQ(ReadBytes(folder + "/old.csv"), "old");
  EXPECT_EQ(FolderEntries(folder), std::vector<std::string>{"old.csv"});
}

// A real full file system: a 64 KiB tmpfs.
TEST(WriteFileAtomically, FullFileSystemKeepsThePreviousFile) {
  testing::SmallFileSystem fs;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, 64 * 1024);
  const size_t free_at_start = fs.FreeBytes();
  const std::string path = fs.path() + "/result.json";
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path, std::string(10000, 'a'), &error))
      << error;
  // Too large for what is left (and for the whole file system).
  EXPECT_FALSE(WriteFileAtomically(path, std::string(200000, 'b'), &error));
  EXPECT_TRUE(Contains(error, path));
  EXPECT_TRUE(Contains(error, std::strerror(ENOSPC)));
  EXPECT_EQ(ReadBytes(path), std::string(10000, 'a'));
  EXPECT_EQ(FolderEntries(fs.path()), std::vector<std::string>{"result.json"});

  // Full to the last block: even a few bytes fail, and nothing is lost.
  fs.Fill();
  ASSERT_EQ(fs.FreeBytes(), 0u);
  EXPECT_FALSE(WriteFileAtomically(path, "tiny", &error));
  EXPECT_TRUE(Contains(error, std::strerror(ENOSPC)));
  EXPECT_EQ(ReadBytes(path), std::string(10000, 'a'));
  EXPECT_EQ(FolderEntries(fs.path()),
            (std::vector<std::string>{"filler", "result.json"}));
  std::filesystem::remove(fs.path() + "/filler");
  std::filesystem::remove(path);
  EXPECT_EQ(fs.FreeBytes(), free_at_start);
}

// Injected failure without root: a file size limit (RLIMIT_FSIZE) in a child
// process makes write() fail with EFBIG once the limit is reached.
TEST(WriteFileAtomically, FileSizeLimitKeepsThePreviousFile) {
  const std::string folder = FreshFolder();
  const std::string path = folder + "/trajectory.txt";
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path, "previous\n", &error)) << error;
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{16 * 1024, 16 * 1024};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(10);
    std::string child_error;
    if (WriteFileAtomically(path, std::string(64 * 1024, 'x'), &child_error))
      ::_exit(11);
    if (child_error.find(std::strerror(EFBIG)) == std::string::npos)
      ::_exit(12);
    if (child_error.find(path) == std::string::npos) ::_exit(13);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status))
      << "child killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0)
      << "10: setrlimit failed, 11: the write succeeded, 12: no EFBIG in "
         "the error, 13: no path in the error";
  EXPECT_EQ(ReadBytes(path), "previous\n");
  EXPECT_EQ(FolderEntries(folder), std::vector<std::string>{"trajectory.txt"});
}

// Two threads and two processes write one path over and over: every write
// succeeds and the file is always one writer's complete output.
TEST(WriteFileAtomically, ConcurrentWritersOfOnePathNeverCollide) {
  const std::string folder = FreshFolder();
  const std::string path = folder + "/map.bin";
  const std::string contents[2] = {std::string(100000, '1'),
                                   std::string(50000, '2')};
  std::atomic<int> failures{0};
  std::atomic<int> ready{0};
  auto writer = [&](int k) {
    ready.fetch_add(1);
    while (ready.load() < 2) {
    }
    for (int i = 0; i < 100; ++i) {
      std::string error;
      if (!WriteFileAtomically(path, contents[k], &error)) ++failures;
    }
  };
  std::thread first(writer, 0);
  std::thread second(writer, 1);
  // Meanwhile the file is only ever one of the two contents.
  for (int i = 0; i < 200; ++i) {
    const std::string now = ReadBytes(path);
    EXPECT_TRUE(now.empty() || now == contents[0] || now == contents[1])
        << now.size() << " bytes";
  }
  first.join();
  second.join();
  EXPECT_EQ(failures.load(), 0);

  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  int child_failures = 0;
  for (int i = 0; i < 100; ++i) {
    std::string error;
    if (!WriteFileAtomically(path, contents[pid == 0 ? 0 : 1], &error))
      ++child_failures;
  }
  if (pid == 0) ::_exit(child_failures == 0 ? 0 : 1);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(child_failures, 0);
  const std::string last = ReadBytes(path);
  EXPECT_TRUE(last == contents[0] || last == contents[1]);
  EXPECT_EQ(FolderEntries(folder), std::vector<std::string>{"map.bin"});
}

// Issue 27 item 11: a writer killed between creating its temporary file and
// the rename leaves ".map.bin.tmp.XXXXXX"; the next write of map.bin
// removes it, but not a temporary file another writer still holds (locked),
// nor files of other targets or of other name patterns.
TEST(WriteFileAtomically, NextWriteRemovesStaleTemporariesOfItsTarget) {
  const std::string folder = FreshFolder();
  const std::vector<std::string> planted = {".map.bin.tmp.AbC123",
                                            ".map.bin.tmp.Held12",
                                            ".other.bin.tmp.AbC123",
                                            ".map.bin.tmp.toolong7",
                                            ".map.bin.tmp.AB-123"};
  for (const std::string& name : planted) {
    std::ofstream(folder + "/" + name) << "half a map";
  }
  // A live writer's temporary file: open and locked, as WriteFileAtomically
  // holds its own.
  const int held = ::open((folder + "/.map.bin.tmp.Held12").c_str(), O_RDONLY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX), 0);
  // A stale one that is a symbolic link is not followed or removed.
  std::filesystem::create_symlink(folder + "/.other.bin.tmp.AbC123",
                                  folder + "/.map.bin.tmp.Link12");

  std::string error;
  ASSERT_TRUE(WriteFileAtomically(folder + "/map.bin", "map", &error)) << error;
  ::close(held);
  EXPECT_EQ(ReadBytes(folder + "/map.bin"), "map");
  EXPECT_EQ(FolderEntries(folder),
            (std::vector<std::string>{".map.bin.tmp.AB-123",
                                      ".map.bin.tmp.Held12",
                                      ".map.bin.tmp.Link12",
                                      ".map.bin.tmp.toolong7",
                                      ".other.bin.tmp.AbC123",
                                      "map.bin"}));
  EXPECT_EQ(ReadBytes(folder + "/.other.bin.tmp.AbC123"), "half a map");
  // Unlocked now: stale, removed by the next write.
  ASSERT_TRUE(WriteFileAtomically(folder + "/map.bin", "map 2", &error))
      << error;
  EXPECT_FALSE(std::filesystem::exists(folder + "/.map.bin.tmp.Held12"));
}

}  // namespace
}  // namespace mlndt
