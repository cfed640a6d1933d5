#include "mlndt/cloud/io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/scratch_dir.h"
#include "tests/testing/small_file_system.h"

namespace mlndt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- Helpers ----------------------------------------------------------------

// A path under the test temp dir, unique per test.
std::string TempPath(const std::string& name) {
  return testing::ScratchPath(name);
}

std::string WriteFile(const std::string& name, const std::string& bytes) {
  const std::string path = TempPath(name);
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << bytes;
  EXPECT_TRUE(file.good()) << path;
  return path;
}

std::string ReadBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << file.rdbuf();
  return buffer.str();
}

// Appends the raw bytes of `value` in the requested byte order.
template <typename T>
void Append(T value, std::string* out, bool big_endian = false) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian)
    std::reverse(bytes, bytes + sizeof(T));  // Host is little-endian.
  out->append(bytes, sizeof(T));
}

::testing::AssertionResult Contains(const std::string& text,
                                    const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "'" << text << "' does not contain '" << part << "'";
}

// Reading `path` must fail, leave the cloud empty, and name the file and the
// problem.
void ExpectReadFails(const std::string& path, const std::string& keyword) {
  PointCloud cloud(std::vector<Eigen::Vector3d>{Eigen::Vector3d(1, 2, 3)});
  ReadCloudInfo info;
  std::string error;
  EXPECT_FALSE(ReadPointCloud(path, &cloud, &info, &error));
  EXPECT_TRUE(cloud.empty());
  EXPECT_TRUE(Contains(error, path));
  EXPECT_TRUE(Contains(error, keyword));
}

PointCloud ReadOk(const std::string& path, ReadCloudInfo* info = nullptr) {
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(path, &cloud, info, &error)) << error;
  return cloud;
}

void ExpectPoints(const PointCloud& cloud,
                  const std::vector<Eigen::Vector3d>& expected) {
  ASSERT_EQ(cloud.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(cloud[i], expected[i])
        << "point " << i << ": " << cloud[i].transpose() << " vs "
        << expected[i].transpose();
  }
}

// A small but real LZF compressor (greedy, brute-force match search) so the
// tests can build binary_compressed PCD bodies without linking liblzf. LZF
// stream: a control byte < 32 starts a literal run of ctrl+1 bytes; otherwise
// its top 3 bits are the match length - 2 (7 = one more length byte follows)
// and its low 5 bits plus the next byte are the distance - 1.
std::string LzfCompress(const std::string& in) {
  std::string out, literal;
  auto flush = [&]() {
    while (!literal.empty()) {
      const size_t n = std::min<size_t>(32, literal.size());
      out.push_back(static_cast<char>(n - 1));
      out.append(literal, 0, n);
      literal.erase(0, n);
    }
  };
  size_t i = 0;
  while (i < in.size()) {
    size_t best_length = 0, best_distance = 0;
    for (size_t distance = 1; distance <= std::min<size_t>(i, 8192);
         ++distance) {
      size_t length = 0;
      while (i + length < in.size() && length < 264 &&
             in[i + length] == in[i + length - distance]) {
        ++length;
      }
      if (length > best_length) {
        best_length = length;
        best_distance = distance;
      }
    }
    if (best_length >= 3) {
      flush();
      const size_t offset = best_distance - 1;
      const size_t code = best_length - 2;
      if (code < 7) {
        out.push_back(static_cast<char>((code << 5) | (offset >> 8)));
      } else {
        out.push_back(static_cast<char>((7 << 5) | (offset >> 8)));
        out.push_back(static_cast<char>(code - 7));
      }
      out.push_back(static_cast<char>(offset & 0xff));
      i += best_length;
    } else {
      literal.push_back(in[i++]);
    }
  }
  flush();
  return out;
}

std::string PcdHeader(const std::string& fields,
                      const std::string& sizes,
                      const std::string& types,
                      const std::string& counts,
                      size_t width,
                      size_t height,
                      const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " +
         fields + "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts +
         "\nWIDTH " + std::to_string(width) + "\nHEIGHT " +
         std::to_string(height) + "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string(width * height) + "\nDATA " + data + "\n";
}

// x y z as float32 records, no extra fields.
std::string XyzF4Pcd(const std::vector<Eigen::Vector3d>& points) {
  std::string bytes =
      PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", points.size(), 1, "binary");
  for (const Eigen::Vector3d& p : points) {
    for (int i = 0; i < 3; ++i) Append(static_cast<float>(p[i]), &bytes);
  }
  return bytes;
}

// Points whose coordinates are exact in float32.
const std::vector<Eigen::Vector3d> kPoints = {
    Eigen::Vector3d(1.5, -2.25, 3.0),
    Eigen::Vector3d(static_cast<float>(0.1), static_cast<float>(-71.3), 1e-3f),
    Eigen::Vector3d(80.0, 1e6, -0.0078125),
};

// ---- Round trips ------------------------------------------------------------

TEST(WritePointCloud, PcdRoundTripIsExact) {
  const std::string path = TempPath("cloud.pcd");
  std::string error;
  ASSERT_TRUE(WritePointCloud(path, PointCloud(kPoints), &error)) << error;
  const std::string bytes = ReadBytes(path);
  EXPECT_EQ(bytes.rfind("# .PCD v0.7", 0), 0u);
  EXPECT_TRUE(Contains(bytes, "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"));
  EXPECT_TRUE(Contains(bytes, "POINTS 3\nDATA binary\n"));
  EXPECT_EQ(bytes.size(), bytes.find("DATA binary\n") + 12 + 3 * 12);

  ReadCloudInfo info;
  const PointCloud cloud = ReadOk(path, &info);
  ExpectPoints(cloud, kPoints);
  EXPECT_EQ(info.format, CloudFormat::PCD);
  EXPECT_EQ(info.points_in_file, 3u);
  EXPECT_EQ(info.dropped_non_finite, 0u);
}

TEST(WritePointCloud, PlyRoundTripIsExact) {
  const std::string path = TempPath("cloud.ply");
  std::string error;
  ASSERT_TRUE(WritePointCloud(path, PointCloud(kPoints), &error)) << error;
  const std::string bytes = ReadBytes(path);
  EXPECT_EQ(bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_TRUE(Contains(bytes,
                       "element vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nend_header\n"));

  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info), kPoints);
  EXPECT_EQ(info.format, CloudFormat::PLY);
  EXPECT_EQ(info.points_in_file, 3u);
}

TEST(WritePointCloud, EmptyCloudRoundTrips) {
  for (const char* name : {"empty.pcd", "empty.ply"}) {
    const std::string path = TempPath(name);
    std::string error;
    ASSERT_TRUE(WritePointCloud(path, PointCloud(), &error)) << error;
    EXPECT_TRUE(ReadOk(path).empty()) << name;
  }
}

TEST(WritePointCloud, ReplacesExistingFileAndLeavesNoTemporaryFile) {
  const std::string path = TempPath("replace.pcd");
  std::string error;
  ASSERT_TRUE(WritePointCloud(path, PointCloud(kPoints), &error)) << error;
  const PointCloud one(std::vector<Eigen::Vector3d>{Eigen::Vector3d(4, 5, 6)});
  ASSERT_TRUE(WritePointCloud(path, one, &error)) << error;
  ExpectPoints(ReadOk(path), one.points());

  const std::string prefix = std::filesystem::path(path).filename().string();
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(path).parent_path())) {
    // Temporary files are ".<name>.tmp.XXXXXX" (atomic_file.h).
    if (entry.path().filename().string().find(prefix) != std::string::npos)
      ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(WritePointCloud, UnsupportedFormatFailsAndWritesNothing) {
  for (const char* name : {"out.xyz", "out.bin", "out.3d"}) {
    const std::string path = TempPath(name);
    std::string error;
    EXPECT_FALSE(WritePointCloud(path, PointCloud(kPoints), &error));
    EXPECT_TRUE(Contains(error, path));
    EXPECT_TRUE(Contains(error, "not supported"));
    EXPECT_FALSE(std::filesystem::exists(path));
  }
}

TEST(WritePointCloud, UnknownExtensionFails) {
  std::string error;
  EXPECT_FALSE(
      WritePointCloud(TempPath("out.las"), PointCloud(kPoints), &error));
  EXPECT_TRUE(Contains(error, "unknown extension"));
}

TEST(WritePointCloud, MissingFolderFails) {
  const std::string path = TempPath("no_such_folder") + "/cloud.pcd";
  std::string error;
  EXPECT_FALSE(WritePointCloud(path, PointCloud(kPoints), &error));
  EXPECT_TRUE(Contains(error, path));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(WritePointCloud, FailedRenameRemovesTemporaryFileAndKeepsTarget) {
  // The target is a non-empty directory, so the final rename fails.
  const std::string path = TempPath("occupied.pcd");
  std::filesystem::create_directories(path);
  std::ofstream(path + "/keep.txt") << "keep";
  std::string error;
  EXPECT_FALSE(WritePointCloud(path, PointCloud(kPoints), &error));
  EXPECT_TRUE(Contains(error, path));
  EXPECT_TRUE(std::filesystem::is_directory(path));
  EXPECT_TRUE(std::filesystem::exists(path + "/keep.txt"));
  const std::string prefix =
      std::filesystem::path(path).filename().string() + ".tmp";
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(path).parent_path())) {
    EXPECT_EQ(entry.path().filename().string().find(prefix), std::string::npos)
        << entry.path();
  }
}

// ---- Atomic writes: special targets, file modes, a full disk ---------------

// A fresh, empty folder for one test.
std::string FreshFolder(const std::string& name) {
  const std::string path = TempPath(name);
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

std::vector<std::string> FolderEntries(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

mode_t CurrentUmask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

TEST(WritePointCloud, RefusesSymlinkFifoAndDeviceTargetsAndLeavesThemAlone) {
  const std::string folder = FreshFolder("special");
  const std::string victim = folder + "/victim.pcd";
  std::ofstream(victim) << "victim";
  const std::string link = folder + "/link.pcd";
  ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
  const std::string fifo = folder + "/fifo.pcd";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  // A copy of /dev/null (needs root; otherwise that case is left out).
  const std::string device = folder + "/device.ply";
  const bool have_device =
      ::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;

  std::string error;
  EXPECT_FALSE(WritePointCloud(link, PointCloud(kPoints), &error));
  EXPECT_TRUE(Contains(error, link));
  EXPECT_TRUE(Contains(error, "symbolic link"));
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(ReadBytes(victim), "victim");

  EXPECT_FALSE(WritePointCloud(fifo, PointCloud(kPoints), &error));
  EXPECT_TRUE(Contains(error, fifo));
  EXPECT_TRUE(Contains(error, "FIFO"));
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));

  if (have_device) {
    EXPECT_FALSE(WritePointCloud(device, PointCloud(kPoints), &error));
    EXPECT_TRUE(Contains(error, device));
    EXPECT_TRUE(Contains(error, "device"));
    EXPECT_TRUE(std::filesystem::is_character_file(device));
  }
  std::vector<std::string> expected = {"fifo.pcd", "link.pcd", "victim.pcd"};
  if (have_device) expected.insert(expected.begin(), "device.ply");
  EXPECT_EQ(FolderEntries(folder), expected);  // No temporary file left.
}

TEST(WritePointCloud, ReplacingKeepsTheFileModeAndNewFilesGet0644) {
  const std::string folder = FreshFolder("mode");
  const std::string path = folder + "/private.pcd";
  std::string error;
  ASSERT_TRUE(WritePointCloud(path, PointCloud(kPoints), &error)) << error;
  struct stat status;
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, 0644 & ~CurrentUmask());

  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  ASSERT_TRUE(WritePointCloud(path, PointCloud(), &error)) << error;
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, 0600u);
  EXPECT_TRUE(ReadOk(path).empty());
}

TEST(WritePointCloud, FullFileSystemKeepsThePreviousFile) {
  testing::SmallFileSystem fs;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, 64 * 1024);
  const size_t free_at_start = fs.FreeBytes();
  for (const char* name : {"cloud.pcd", "cloud.ply"}) {
    const std::string path = fs.path() + "/" + name;
    std::string error;
    ASSERT_TRUE(WritePointCloud(path, PointCloud(kPoints), &error)) << error;
    const std::string before = ReadBytes(path);
    // 20000 points = 240 kB of float32 data: far more than the 64 kB disk.
    std::vector<Eigen::Vector3d> many(20000, Eigen::Vector3d(1, 2, 3));
    EXPECT_FALSE(WritePointCloud(path, PointCloud(many), &error));
    EXPECT_TRUE(Contains(error, path)) << error;
    EXPECT_TRUE(Contains(error, std::strerror(ENOSPC))) << error;
    EXPECT_EQ(ReadBytes(path), before) << name;
    EXPECT_EQ(FolderEntries(fs.path()), std::vector<std::string>{name});
    ASSERT_EQ(::unlink(path.c_str()), 0);
  }
  EXPECT_EQ(fs.FreeBytes(), free_at_start);  // Nothing leaked.
}

// ---- PCD --------------------------------------------------------------------

TEST(ReadPcd, AsciiWithCommentsAndNaN) {
  const std::string path =
      WriteFile("ascii.pcd",
                "# .PCD v0.7 - Point Cloud Data file format\n"
                "VERSION 0.7\n"
                "FIELDS x y z rgb\n"
                "SIZE 4 4 4 4\n"
                "TYPE F F F F\n"
                "COUNT 1 1 1 1\n"
                "WIDTH 3\n"
                "HEIGHT 1\n"
                "VIEWPOINT 0 0 0 1 0 0 0\n"
                "POINTS 3\n"
                "DATA ascii\n"
                "1.5 -2 3e-1 4.2108e+06\n"
                "nan nan nan 0\n"
                "\n"
                "+7 8 9 0\n");
  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info),
               {Eigen::Vector3d(1.5, -2, 0.3), Eigen::Vector3d(7, 8, 9)});
  EXPECT_EQ(info.points_in_file, 3u);
  EXPECT_EQ(info.dropped_non_finite, 1u);
}

TEST(ReadPcd, Version06HeaderWithoutVersionAndCountAndCrLf) {
  const std::string path =
      WriteFile("v06.pcd",
                "# .PCD v.6 - Point Cloud Data file format\r\n"
                "FIELDS x y z\r\n"
                "SIZE 4 4 4\r\n"
                "TYPE F F F\r\n"
                "WIDTH 2\r\n"
                "HEIGHT 1\r\n"
                "POINTS 2\r\n"
                "DATA ascii\r\n"
                "1 2 3\r\n"
                "4 5 6\r\n");
  ExpectPoints(ReadOk(path),
               {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)});
}

TEST(ReadPcd, AsciiCountAndPaddingFieldsEitherLayout) {
  // '_' has COUNT 2 and comes before x: a line with 8 values includes the
  // padding values (PCL's reader), one with 6 omits them (PCL's writer).
  const std::string path = WriteFile("padding.pcd",
                                     PcdHeader("_ x y z normal",
                                               "1 4 4 4 4",
                                               "U F F F F",
                                               "2 1 1 1 3",
                                               2,
                                               1,
                                               "ascii") +
                                         "0 0 1 2 3 0.5 0.5 0.7\n"
                                         "4 5 6 0.5 0.5 0.7\n");
  ExpectPoints(ReadOk(path),
               {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)});
}

TEST(ReadPcd, BinaryWithExtraFieldsCountsPaddingAndMixedSizes) {
  // Record: intensity U2 | x F4 | normal F4 x3 | y F8 | _ U1 x3 | z F4 | ring
  // I1
  const std::vector<Eigen::Vector3d> expected = {
      Eigen::Vector3d(1.25, -2.5e-3, 100), Eigen::Vector3d(-7, 0.1, 3.5)};
  std::string bytes = PcdHeader("intensity x normal y _ z ring",
                                "2 4 4 8 1 4 1",
                                "U F F F U F I",
                                "1 1 3 1 3 1 1",
                                2,
                                1,
                                "binary");
  for (const Eigen::Vector3d& p : expected) {
    Append<uint16_t>(65535, &bytes);
    Append(static_cast<float>(p.x()), &bytes);
    for (int i = 0; i < 3; ++i) Append(12345.f, &bytes);
    Append(p.y(), &bytes);  // F8: the full double survives.
    bytes.append(3, '\x7f');
    Append(static_cast<float>(p.z()), &bytes);
    Append<int8_t>(-3, &bytes);
  }
  ExpectPoints(ReadOk(WriteFile("extra.pcd", bytes)), expected);
}

TEST(ReadPcd, BinaryDoublePrecisionXyz) {
  const std::vector<Eigen::Vector3d> expected = {
      Eigen::Vector3d(0.1, 0.2, 0.3),
      Eigen::Vector3d(1e-12, -123456.789, 1.0 / 3)};
  std::string bytes =
      PcdHeader("x y z", "8 8 8", "F F F", "1 1 1", 2, 1, "binary");
  for (const Eigen::Vector3d& p : expected) {
    for (int i = 0; i < 3; ++i) Append(p[i], &bytes);
  }
  ExpectPoints(ReadOk(WriteFile("f8.pcd", bytes)), expected);
}

TEST(ReadPcd, OrganisedBinaryDropsNaN) {
  const std::string path = WriteFile("organised.pcd", [] {
    std::string bytes =
        PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 2, 2, "binary");
    const float values[4][3] = {
        {1, 2, 3}, {NAN, NAN, NAN}, {4, 5, 6}, {7, INFINITY, 9}};
    for (const auto& p : values) {
      for (float v : p) Append(v, &bytes);
    }
    return bytes;
  }());
  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info),
               {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)});
  EXPECT_EQ(info.points_in_file, 4u);
  EXPECT_EQ(info.dropped_non_finite, 2u);
}

// A binary_compressed body: field-major data, LZF-compressed, behind its two
// uint32 sizes.
std::string CompressedBody(const std::string& field_major) {
  const std::string packed = LzfCompress(field_major);
  std::string body;
  Append<uint32_t>(static_cast<uint32_t>(packed.size()), &body);
  Append<uint32_t>(static_cast<uint32_t>(field_major.size()), &body);
  return body + packed;
}

TEST(ReadPcd, BinaryCompressedFieldMajorWithExtraFields) {
  // FIELDS x(F8) y z normal(F4 x3) label(U4); 40 points on a line so the data
  // has repeats for LZF back references.
  const int n = 40;
  std::vector<Eigen::Vector3d> expected;
  for (int i = 0; i < n; ++i)
    expected.emplace_back(0.5 * i, -1.0, 0.25 * (i % 4));
  std::string field_major;
  for (const auto& p : expected) Append(p.x(), &field_major);
  for (const auto& p : expected)
    Append(static_cast<float>(p.y()), &field_major);
  for (const auto& p : expected)
    Append(static_cast<float>(p.z()), &field_major);
  for (int i = 0; i < n; ++i) {
    for (float v : {0.f, 0.f, 1.f}) Append(v, &field_major);
  }
  for (int i = 0; i < n; ++i) Append<uint32_t>(7, &field_major);
  ASSERT_EQ(field_major.size(), static_cast<size_t>(n) * (8 + 4 + 4 + 12 + 4));
  const std::string body = CompressedBody(field_major);
  ASSERT_LT(body.size(), field_major.size());  // Back references were used.

  const std::string path = WriteFile("compressed.pcd",
                                     PcdHeader("x y z normal label",
                                               "8 4 4 4 4",
                                               "F F F F U",
                                               "1 1 1 3 1",
                                               n,
                                               1,
                                               "binary_compressed") +
                                         body);
  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info), expected);
  EXPECT_EQ(info.points_in_file, static_cast<size_t>(n));
}

TEST(ReadPcd, BinaryCompressedDropsNaN) {
  std::string field_major;
  for (float v : {1.f, NAN, 2.f}) Append(v, &field_major);  // x
  for (float v : {3.f, 0.f, 4.f}) Append(v, &field_major);  // y
  for (float v : {5.f, 0.f, 6.f}) Append(v, &field_major);  // z
  const std::string path = WriteFile(
      "compressed_nan.pcd",
      PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 3, 1, "binary_compressed") +
          CompressedBody(field_major));
  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info),
               {Eigen::Vector3d(1, 3, 5), Eigen::Vector3d(2, 4, 6)});
  EXPECT_EQ(info.dropped_non_finite, 1u);
}

// ---- PCD errors
// ---------------------------------------------------------------

// A header that declares 0 points is a valid, empty cloud (WritePointCloud
// writes such files for an empty cloud); 0 bytes is not a PCD/PLY file.
TEST(ReadPcd, HeaderWithZeroPointsIsAnEmptyCloud) {
  for (const char* data : {"ascii", "binary"}) {
    ReadCloudInfo info;
    EXPECT_TRUE(
        ReadOk(WriteFile(
                   std::string("zero_") + data + ".pcd",
                   PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 0, 1, data)),
               &info)
            .empty());
    EXPECT_EQ(info.points_in_file, 0u);
  }
  EXPECT_TRUE(ReadOk(WriteFile("zero.ply",
                               "ply\nformat ascii 1.0\nelement vertex 0\n"
                               "property float x\nproperty float y\n"
                               "property float z\nend_header\n"))
                  .empty());
}

TEST(ReadPcdErrors, EmptyFile) {
  ExpectReadFails(WriteFile("empty.pcd", ""), "empty file");
}

TEST(ReadPcdErrors, BadMagic) {
  ExpectReadFails(WriteFile("magic.pcd", "hello world\n1 2 3\n"),
                  "not a PCD header");
  ExpectReadFails(WriteFile("ply_named_pcd.pcd", "ply\nformat ascii 1.0\n"),
                  "not a PCD header");
}

TEST(ReadPcdErrors, NoDataLine) {
  ExpectReadFails(
      WriteFile("nodata.pcd", "# only a comment\nVERSION 0.7\nFIELDS x y z\n"),
      "no DATA line");
}

TEST(ReadPcdErrors, UnsupportedVersion) {
  ExpectReadFails(WriteFile("version.pcd", "VERSION 2.0\nFIELDS x y z\n"),
                  "unsupported VERSION");
}

TEST(ReadPcdErrors, XyzMustBeFloat) {
  // x as U4, y as I2, z as F2 (unsupported SIZE), x with COUNT 2.
  ExpectReadFails(
      WriteFile("u4.pcd",
                PcdHeader("x y z", "4 4 4", "U F F", "1 1 1", 1, 1, "binary") +
                    std::string(12, '\0')),
      "unsupported TYPE/SIZE for field x");
  ExpectReadFails(
      WriteFile("i2.pcd",
                PcdHeader("x y z", "4 2 4", "F I F", "1 1 1", 1, 1, "binary") +
                    std::string(10, '\0')),
      "unsupported TYPE/SIZE for field y");
  ExpectReadFails(
      WriteFile("f2.pcd",
                PcdHeader("x y z", "4 4 2", "F F F", "1 1 1", 1, 1, "binary") +
                    std::string(10, '\0')),
      "unsupported TYPE/SIZE for field z");
  ExpectReadFails(
      WriteFile("count2.pcd",
                PcdHeader("x y z", "4 4 4", "F F F", "2 1 1", 1, 1, "binary") +
                    std::string(16, '\0')),
      "unsupported TYPE/SIZE for field x");
}

TEST(ReadPcdErrors, UnknownTypeLetterOrZeroSize) {
  ExpectReadFails(
      WriteFile(
          "q.pcd",
          PcdHeader(
              "x y z rgb", "4 4 4 4", "F F F Q", "1 1 1 1", 1, 1, "binary")),
      "unsupported TYPE 'Q' for field rgb");
  ExpectReadFails(
      WriteFile(
          "size0.pcd",
          PcdHeader(
              "x y z rgb", "4 4 4 0", "F F F U", "1 1 1 1", 1, 1, "binary")),
      "unsupported SIZE '0' for field rgb");
}

TEST(ReadPcdErrors, UnsupportedDataKind) {
  ExpectReadFails(
      WriteFile(
          "lz4.pcd",
          PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 1, 1, "binary_lz4")),
      "unsupported DATA");
}

TEST(ReadPcdErrors, MissingXyzField) {
  ExpectReadFails(
      WriteFile(
          "noz.pcd",
          PcdHeader("x y intensity", "4 4 4", "F F F", "1 1 1", 1, 1, "ascii") +
              "1 2 3\n"),
      "missing field z");
}

TEST(ReadPcdErrors, SizeTypeCountEntriesMustMatchFields) {
  ExpectReadFails(
      WriteFile("entries.pcd",
                PcdHeader("x y z", "4 4", "F F F", "1 1 1", 1, 1, "ascii") +
                    "1 2 3\n"),
      "FIELDS has 3 entries but SIZE has 2");
}

TEST(ReadPcdErrors, PointsDisagreesWithWidthTimesHeight) {
  ExpectReadFails(
      WriteFile("points.pcd",
                "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\n"
                "HEIGHT 2\nPOINTS 5\nDATA ascii\n1 2 3\n"),
      "header/count mismatch: POINTS is 5 but WIDTH*HEIGHT is 2*2 = 4");
}

TEST(ReadPcdErrors, AsciiFewerLinesThanPoints) {
  ExpectReadFails(
      WriteFile("few.pcd",
                PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 3, 1, "ascii") +
                    "1 2 3\n4 5 6\n"),
      "header/count mismatch: POINTS is 3 but the ascii body has only 2");
}

TEST(ReadPcdErrors, AsciiMoreLinesThanPoints) {
  ExpectReadFails(
      WriteFile("many.pcd",
                PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 1, 1, "ascii") +
                    "1 2 3\n4 5 6\n"),
      "header/count mismatch");
}

TEST(ReadPcdErrors, AsciiUnparsableValueNamesLine) {
  // The header is 11 lines, so the second point is on line 13.
  ExpectReadFails(
      WriteFile("value.pcd",
                PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 2, 1, "ascii") +
                    "1 2 3\n4 5 abc\n"),
      "line 13: cannot parse z value 'abc'");
  ExpectReadFails(
      WriteFile("tokens.pcd",
                PcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 2, 1, "ascii") +
                    "1 2 3\n4 5\n"),
      "line 13: cannot parse point: expected 3 values");
}

TEST(ReadPcdErrors, TruncatedBinaryBody) {
  // 100 points of 32 bytes need 3200 bytes; the file has 1000.
  const std::string path = WriteFile(
      "truncated.pcd",
      PcdHeader("x y z intensity normal_x normal_y normal_z curvature",
                "4 4 4 4 4 4 4 4",
                "F F F F F F F F",
                "1 1 1 1 1 1 1 1",
                100,
                1,
                "binary") +
          std::string(1000, '\0'));
  ExpectReadFails(path, "truncated binary body");
  PointCloud cloud;
  std::string error;
  EXPECT_FALSE(ReadPointCloud(path, &cloud, nullptr, &error));
  EXPECT_EQ(error,
            path + ": truncated binary body: expected 3200 bytes, found 1000");
}

TEST(ReadPcdErrors, AbsurdPointCountsAreCheckedBeforeAllocating) {
  // 4e9 points or an overflowing WIDTH*point size: both must fail quickly.
  ExpectReadFails(
      WriteFile(
          "huge.pcd",
          PcdHeader(
              "x y z", "4 4 4", "F F F", "1 1 1", 4000000000u, 1, "binary") +
              std::string(24, '\0')),
      "truncated binary body: expected 48000000000 bytes, found 24");
  ExpectReadFails(
      WriteFile(
          "overflow.pcd",
          "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 18446744073709551615\n"
          "HEIGHT 1\nDATA binary\n"),
      "truncated binary body");
  ExpectReadFails(
      WriteFile(
          "huge_ascii.pcd",
          PcdHeader(
              "x y z", "4 4 4", "F F F", "1 1 1", 4000000000u, 1, "ascii") +
              "1 2 3\n"),
      "header/count mismatch");
  ExpectReadFails(WriteFile(
                      "huge_compressed.pcd",
                      PcdHeader("x y z",
                                "4 4 4",
                                "F F F",
                                "1 1 1",
                                100000000,
                                1,
                                "binary_compressed") +
                          [] {
                            std::string sizes;
                            Append<uint32_t>(4, &sizes);
                            Append<uint32_t>(1200000000u, &sizes);
                            return sizes + std::string("\x1f\x00\x00\x00", 4);
                          }()),
                  "corrupt binary_compressed body");
}

std::string CompressedPcdWithBody(const std::string& body) {
  return PcdHeader(
             "x y z", "4 4 4", "F F F", "1 1 1", 2, 1, "binary_compressed") +
         body;
}

TEST(ReadPcdErrors, CompressedBodyTooShortForSizes) {
  ExpectReadFails(
      WriteFile("short.pcd", CompressedPcdWithBody("abc")),
      "corrupt binary_compressed body: expected 8 bytes of sizes, found 3");
}

TEST(ReadPcdErrors, CompressedSizeBeyondFile) {
  std::string body;
  Append<uint32_t>(1000, &body);
  Append<uint32_t>(24, &body);
  body += std::string(10, '\0');
  ExpectReadFails(WriteFile("beyond.pcd", CompressedPcdWithBody(body)),
                  "corrupt binary_compressed body: compressed size 1000 but "
                  "only 10 bytes follow");
}

TEST(ReadPcdErrors, UncompressedSizeDisagreesWithHeader) {
  std::string field_major(24, '\0');
  std::string body = CompressedBody(field_major);
  body[4] = 20;  // Uncompressed size 20 instead of 2 points * 12 bytes.
  ExpectReadFails(WriteFile("usize.pcd", CompressedPcdWithBody(body)),
                  "corrupt binary_compressed body: uncompressed size 20");
}

TEST(ReadPcdErrors, LzfDecompressionFails) {
  // A back reference before the start of the output is invalid LZF.
  std::string body;
  Append<uint32_t>(4, &body);
  Append<uint32_t>(24, &body);
  body += std::string("\x20\x05\x00\x00", 4);
  ExpectReadFails(WriteFile("lzf.pcd", CompressedPcdWithBody(body)),
                  "LZF decompression failed");
  // Valid LZF that decompresses to too few bytes.
  std::string short_body = CompressedBody(std::string(12, '\1'));
  short_body[4] = 24;
  ExpectReadFails(WriteFile("lzf_short.pcd", CompressedPcdWithBody(short_body)),
                  "LZF decompression failed");
}

// ---- PLY --------------------------------------------------------------------

TEST(ReadPly, AsciiWithCommentsExtraPropertiesAndFaces) {
  const std::string path = WriteFile("ascii.ply",
                                     "ply\n"
                                     "format ascii 1.0\n"
                                     "comment made by hand\n"
                                     "obj_info test object\n"
                                     "element vertex 3\n"
                                     "property uchar red\n"
                                     "property float x\n"
                                     "property float y\n"
                                     "property float z\n"
                                     "property int32 label\n"
                                     "element face 1\n"
                                     "property list uchar int vertex_indices\n"
                                     "end_header\n"
                                     "255 1 2 3 7\n"
                                     "0 4.5 -5 6 -1\n"
                                     "\n"
                                     "1 7 8 9e1 2\n"
                                     "3 0 1 2\n");
  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info),
               {Eigen::Vector3d(1, 2, 3),
                Eigen::Vector3d(4.5, -5, 6),
                Eigen::Vector3d(7, 8, 90)});
  EXPECT_EQ(info.format, CloudFormat::PLY);
}

TEST(ReadPly, BinaryLittleEndianFloatWithExtraProperties) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\ncomment "
      "CloudCompare-like\nelement vertex 2\n"
      "property float x\nproperty float y\nproperty float z\nproperty double "
      "intensity\n"
      "property ushort ring\nelement face 0\nproperty list uchar int "
      "vertex_indices\n"
      "end_header\n";
  const std::vector<Eigen::Vector3d> expected = {
      Eigen::Vector3d(1.5, 2.5, -3.5), Eigen::Vector3d(-0.125, 64, 1024)};
  for (const auto& p : expected) {
    for (int i = 0; i < 3; ++i) Append(static_cast<float>(p[i]), &bytes);
    Append(0.75, &bytes);
    Append<uint16_t>(12, &bytes);
  }
  ExpectPoints(ReadOk(WriteFile("le.ply", bytes)), expected);
}

TEST(ReadPly, BinaryBigEndianDouble) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float64 "
      "x\n"
      "property uint8 flag\nproperty float64 y\nproperty float64 "
      "z\nend_header\n";
  const std::vector<Eigen::Vector3d> expected = {
      Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(-1e5, 1.0 / 3, 42)};
  for (const auto& p : expected) {
    Append(p.x(), &bytes, /*big_endian=*/true);
    bytes.push_back('\x01');
    Append(p.y(), &bytes, /*big_endian=*/true);
    Append(p.z(), &bytes, /*big_endian=*/true);
  }
  ExpectPoints(ReadOk(WriteFile("be.ply", bytes)), expected);
}

TEST(ReadPly, BinaryBigEndianFloat) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float32 "
      "x\n"
      "property float32 y\nproperty float32 z\nend_header\n";
  for (float v : {1.25f, -2.f, 1e-3f}) Append(v, &bytes, /*big_endian=*/true);
  ExpectPoints(ReadOk(WriteFile("be_float.ply", bytes)),
               {Eigen::Vector3d(1.25, -2, static_cast<double>(1e-3f))});
}

TEST(ReadPly, AsciiDouble) {
  const std::string path = WriteFile("ascii_double.ply",
                                     "ply\nformat ascii 1.0\nelement vertex 1\n"
                                     "property double x\nproperty double y\n"
                                     "property double z\nend_header\n"
                                     "0.1 0.2 0.30000000000000004\n");
  ExpectPoints(ReadOk(path), {Eigen::Vector3d(0.1, 0.2, 0.30000000000000004)});
}

TEST(ReadPly, SkipsElementsBeforeTheVertices) {
  // A binary element with a list property, then the vertices.
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement camera 2\nproperty float "
      "fx\n"
      "property list uchar int ids\nelement vertex 1\nproperty float "
      "x\nproperty float y\n"
      "property float z\nend_header\n";
  Append(500.f, &bytes);
  Append<uint8_t>(2, &bytes);
  Append<int32_t>(1, &bytes);
  Append<int32_t>(2, &bytes);
  Append(600.f, &bytes);
  Append<uint8_t>(0, &bytes);
  for (float v : {7.f, 8.f, 9.f}) Append(v, &bytes);
  ExpectPoints(ReadOk(WriteFile("camera.ply", bytes)),
               {Eigen::Vector3d(7, 8, 9)});

  const std::string ascii =
      WriteFile("camera_ascii.ply",
                "ply\nformat ascii 1.0\nelement camera 1\n"
                "property list uchar int ids\nelement vertex 1\n"
                "property float x\nproperty float y\nproperty float z\n"
                "end_header\n3 1 2 3\n4 5 6\n");
  ExpectPoints(ReadOk(ascii), {Eigen::Vector3d(4, 5, 6)});
}

TEST(ReadPly, DropsNaN) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float "
      "x\n"
      "property float y\nproperty float z\nend_header\n";
  for (float v : {NAN, 1.f, 2.f, 3.f, 4.f, 5.f}) Append(v, &bytes);
  ReadCloudInfo info;
  ExpectPoints(ReadOk(WriteFile("nan.ply", bytes), &info),
               {Eigen::Vector3d(3, 4, 5)});
  EXPECT_EQ(info.points_in_file, 2u);
  EXPECT_EQ(info.dropped_non_finite, 1u);
}

// ---- PLY errors
// ---------------------------------------------------------------

const char kPlyXyzFloat[] =
    "property float x\nproperty float y\nproperty float z\n";

TEST(ReadPlyErrors, EmptyFile) {
  ExpectReadFails(WriteFile("empty.ply", ""), "empty file");
}

TEST(ReadPlyErrors, BadMagic) {
  ExpectReadFails(WriteFile("magic.ply", "plyx\nformat ascii 1.0\n"),
                  "not a PLY file");
  ExpectReadFails(WriteFile("pcd_named_ply.ply", "VERSION 0.7\nFIELDS x y z\n"),
                  "not a PLY file");
}

TEST(ReadPlyErrors, BadFormatLine) {
  for (const char* format :
       {"format binary_middle_endian 1.0", "format ascii 2.0", "format"}) {
    ExpectReadFails(
        WriteFile("format.ply",
                  std::string("ply\n") + format + "\nelement vertex 0\n" +
                      kPlyXyzFloat + "end_header\n"),
        "header line 2: bad format line");
  }
}

TEST(ReadPlyErrors, MissingFormatLine) {
  ExpectReadFails(WriteFile("noformat.ply",
                            std::string("ply\nelement vertex 0\n") +
                                kPlyXyzFloat + "end_header\n"),
                  "no format line");
}

TEST(ReadPlyErrors, NoEndHeader) {
  ExpectReadFails(
      WriteFile("noend.ply",
                std::string("ply\nformat ascii 1.0\nelement vertex 1\n") +
                    kPlyXyzFloat),
      "no end_header line");
}

TEST(ReadPlyErrors, NoVertexElement) {
  ExpectReadFails(
      WriteFile(
          "novertex.ply",
          "ply\nformat ascii 1.0\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n3 0 1 2\n"),
      "no vertex element");
}

TEST(ReadPlyErrors, MissingCoordinate) {
  ExpectReadFails(
      WriteFile("noz.ply",
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                "property float y\nend_header\n1 2\n"),
      "missing field z");
}

TEST(ReadPlyErrors, UnsupportedCoordinateType) {
  ExpectReadFails(
      WriteFile("uchar.ply",
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar x\n"
                "property float y\nproperty float z\nend_header\n1 2 3\n"),
      "unsupported type 'uchar' for vertex property x");
}

TEST(ReadPlyErrors, UnknownPropertyType) {
  ExpectReadFails(
      WriteFile("type.ply",
                std::string("ply\nformat ascii 1.0\nelement vertex 1\n") +
                    kPlyXyzFloat + "property quad w\nend_header\n1 2 3 4\n"),
      "unknown property type");
}

TEST(ReadPlyErrors, ListPropertyInVertexElement) {
  ExpectReadFails(
      WriteFile("list.ply",
                std::string("ply\nformat ascii 1.0\nelement vertex 1\n") +
                    kPlyXyzFloat +
                    "property list uchar float extra\nend_header\n"
                    "1 2 3 1 4\n"),
      "unsupported list property 'extra' in the vertex element");
}

TEST(ReadPlyErrors, TruncatedBinaryBody) {
  const std::string path = WriteFile(
      "truncated.ply",
      std::string(
          "ply\nformat binary_little_endian 1.0\nelement vertex 100\n") +
          kPlyXyzFloat + "end_header\n" + std::string(50, '\0'));
  PointCloud cloud;
  std::string error;
  EXPECT_FALSE(ReadPointCloud(path, &cloud, nullptr, &error));
  EXPECT_EQ(error,
            path + ": truncated binary body: expected 1200 bytes, found 50");
  ExpectReadFails(path, "truncated binary body");
}

TEST(ReadPlyErrors, AbsurdVertexCount) {
  ExpectReadFails(
      WriteFile("huge.ply",
                std::string("ply\nformat binary_big_endian 1.0\n"
                            "element vertex 18446744073709551615\n") +
                    kPlyXyzFloat + "end_header\n" + std::string(12, '\0')),
      "truncated binary body");
}

TEST(ReadPlyErrors, TruncatedElementBeforeVertices) {
  ExpectReadFails(
      WriteFile(
          "camera.ply",
          std::string("ply\nformat binary_little_endian 1.0\nelement camera 3\n"
                      "property list uchar int ids\nelement vertex 0\n") +
              kPlyXyzFloat + "end_header\n\x05\x01"),
      "truncated binary body: element 'camera'");
}

TEST(ReadPlyErrors, TruncatedAsciiBody) {
  ExpectReadFails(
      WriteFile("truncated_ascii.ply",
                std::string("ply\nformat ascii 1.0\nelement vertex 3\n") +
                    kPlyXyzFloat + "end_header\n1 2 3\n"),
      "truncated ascii body: expected 3 vertices, found 1");
}

TEST(ReadPlyErrors, AsciiUnparsableLine) {
  ExpectReadFails(
      WriteFile("value.ply",
                std::string("ply\nformat ascii 1.0\nelement vertex 2\n") +
                    kPlyXyzFloat + "end_header\n1 2 3\n4 x 6\n"),
      "line 9: cannot parse y value 'x'");
  ExpectReadFails(
      WriteFile("short_line.ply",
                std::string("ply\nformat ascii 1.0\nelement vertex 1\n") +
                    kPlyXyzFloat + "end_header\n1 2\n"),
      "line 8: cannot parse vertex: expected 3 values, found 2");
}

// ---- KITTI .bin
// ---------------------------------------------------------------

TEST(ReadKittiBin, RecordsOfFourFloats) {
  std::string bytes;
  const float records[3][4] = {
      {1.5f, -2.f, 0.25f, 0.3f}, {NAN, 0, 0, 0}, {80.f, 0.f, -1.75f, 1}};
  for (const auto& r : records) {
    for (float v : r) Append(v, &bytes);
  }
  ReadCloudInfo info;
  ExpectPoints(ReadOk(WriteFile("000000.bin", bytes), &info),
               {Eigen::Vector3d(1.5, -2, 0.25), Eigen::Vector3d(80, 0, -1.75)});
  EXPECT_EQ(info.format, CloudFormat::KITTI_BIN);
  EXPECT_EQ(info.points_in_file, 3u);
  EXPECT_EQ(info.dropped_non_finite, 1u);
}

TEST(ReadKittiBinErrors, EmptyFileHasNoPoints) {
  ExpectReadFails(WriteFile("empty.bin", ""), "no points");
}

TEST(ReadKittiBinErrors, SizeNotMultipleOf16) {
  ExpectReadFails(WriteFile("odd.bin", std::string(20, '\0')),
                  "file size 20 bytes is not a multiple of 16");
}

// ---- 3DTK .3d
// -----------------------------------------------------------------

TEST(ReadUos3d, ConvertsCentimetresLeftHandedToMetresZUp) {
  // 3DTK: x right, y up, z forward [cm]. Ours: x forward, y left, z up [m].
  const std::string path = WriteFile("scan000.3d",
                                     "100 200 300 55\n"
                                     "\n"
                                     "-50 0 1000\n"
                                     "0 -150.5 0\n");
  ReadCloudInfo info;
  ExpectPoints(ReadOk(path, &info),
               {Eigen::Vector3d(3, -1, 2),
                Eigen::Vector3d(10, 0.5, 0),
                Eigen::Vector3d(0, 0, -1.505)});
  EXPECT_EQ(info.format, CloudFormat::UOS_3D);
}

TEST(ReadUos3d, SkipsThe3dtkSizeHeaderLine) {
  ExpectPoints(ReadOk(WriteFile("header.3d", "2 x 1\n100 0 0\n0 0 100\n")),
               {Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(1, 0, 0)});
}

TEST(ReadUos3dErrors, UnparsableLineNamesLineNumber) {
  ExpectReadFails(WriteFile("bad.3d", "1 2 3\n\n4 five 6\n"),
                  "line 3: cannot parse point");
  ExpectReadFails(WriteFile("short.3d", "1 2 3\n4 5\n"),
                  "line 2: cannot parse point");
  // The size header is only allowed on the first line.
  ExpectReadFails(WriteFile("late_header.3d", "1 2 3\n2 x 1\n"),
                  "line 2: cannot parse point");
}

TEST(ReadUos3dErrors, FilesWithoutPointsFail) {
  for (const char* text : {"", "\n", "1200 x 68\n"}) {
    ExpectReadFails(WriteFile("empty.3d", text), "no points");
  }
}

// ---- Plain xyz text
// -----------------------------------------------------------

TEST(ReadXyz, WhitespaceCommasCommentsAndExtraColumns) {
  const std::string text =
      "# x y z intensity\n"
      "1,2,3\n"
      "4 5 6 0.9 extra\n"
      "\n"
      "  7.5\t8 , 9  \r\n"
      "-1e2, +2, nan\n";
  ReadCloudInfo info;
  ExpectPoints(ReadOk(WriteFile("points.xyz", text), &info),
               {Eigen::Vector3d(1, 2, 3),
                Eigen::Vector3d(4, 5, 6),
                Eigen::Vector3d(7.5, 8, 9)});
  EXPECT_EQ(info.format, CloudFormat::XYZ);
  EXPECT_EQ(info.points_in_file, 4u);
  EXPECT_EQ(info.dropped_non_finite, 1u);
  EXPECT_EQ(ReadOk(WriteFile("points.txt", text)).size(), 3u);
}

TEST(ReadXyzErrors, FilesWithoutPointsFail) {
  for (const char* text : {"", "\n\n", "# x y z\n# nothing else\n"}) {
    ExpectReadFails(WriteFile("empty.xyz", text), "no points");
    ExpectReadFails(WriteFile("empty.txt", text), "no points");
  }
}

TEST(ReadXyzErrors, UnparsableLineNamesLineNumber) {
  ExpectReadFails(WriteFile("bad.xyz", "1 2 3\n4 5\n"),
                  "line 2: cannot parse point");
  ExpectReadFails(WriteFile("header.txt", "x,y,z\n1,2,3\n"),
                  "line 1: cannot parse point");
}

// ---- Errors common to all formats
// ---------------------------------------------

TEST(ReadPointCloudErrors, MissingFile) {
  for (const char* name : {"missing.pcd",
                           "missing.ply",
                           "missing.bin",
                           "missing.3d",
                           "missing.xyz"}) {
    ExpectReadFails(TempPath(name), "cannot open file");
  }
}

TEST(ReadPointCloudErrors, Directory) {
  const std::string path = TempPath("folder.pcd");
  std::filesystem::create_directories(path);
  ExpectReadFails(path, "directory");
}

TEST(ReadPointCloudErrors, UnknownExtension) {
  ExpectReadFails(WriteFile("cloud.las", "1 2 3\n"),
                  "unknown extension '.las'");
}

TEST(ReadPointCloudErrors, InfoMayBeNull) {
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(
      WriteFile("null_info.xyz", "1 2 3\n"), &cloud, nullptr, &error));
  EXPECT_EQ(cloud.size(), 1u);
}

}  // namespace
}  // namespace mlndt
