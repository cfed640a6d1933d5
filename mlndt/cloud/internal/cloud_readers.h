#pragma once

// Internals of the cloud and pose file I/O (mlndt/cloud/io.h, pose_io.h):
// one parser per format, the two encoders, whole-file reads (writes go
// through mlndt/common/atomic_file.h) and the small text and byte helpers
// the parsers share. Not public API.
//
// Parser contract: `data` is the whole file. The parser appends every point of
// the file, in file order and in metres, to *points (non-finite ones too: the
// caller counts and drops them). On failure it returns false with *error
// describing the problem WITHOUT the path (ReadPointCloud prefixes
// "<path>: "), and *points holds garbage the caller discards.
// Parsers check every count read from a header against the bytes actually
// present before they allocate anything sized by that count.

#include <Eigen/Core>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {
namespace internal {

// ---- Parsers (one per format; files named after the format). --------------

// pcd_io.cc. PCD v0.7 / v0.6, DATA ascii / binary / binary_compressed.
bool ParsePcd(const std::string& data,
              std::vector<Eigen::Vector3d>* points,
              std::string* error);
// ply_io.cc. PLY 1.0 ascii / binary_little_endian / binary_big_endian.
bool ParsePly(const std::string& data,
              std::vector<Eigen::Vector3d>* points,
              std::string* error);
// kitti_bin_io.cc. float32 x y z intensity records.
bool ParseKittiBin(const std::string& data,
                   std::vector<Eigen::Vector3d>* points,
                   std::string* error);
// uos_io.cc. 3DTK .3d text; converts to metres, right-handed, z up.
bool ParseUos3d(const std::string& data,
                std::vector<Eigen::Vector3d>* points,
                std::string* error);
// xyz_io.cc. Plain "x y z" text.
bool ParseXyzText(const std::string& data,
                  std::vector<Eigen::Vector3d>* points,
                  std::string* error);

// ---- Encoders (the bytes of a whole file). ----------------------------------

// pcd_io.cc. PCD v0.7, FIELDS x y z, SIZE 4, TYPE F, DATA binary.
std::string EncodePcdBinary(const PointCloud& cloud);
// ply_io.cc. PLY binary_little_endian, element vertex with float x y z.
std::string EncodePlyBinary(const PointCloud& cloud);

// ---- Whole files (io.cc). ---------------------------------------------------

// Reads the whole file. On failure *error is "<path>: cannot open ...".
bool ReadFileToString(const std::string& path,
                      std::string* data,
                      std::string* error);

// ---- Text helpers. ----------------------------------------------------------

// Walks `data` line by line. A line ends at '\n'; a '\r' before it (Windows
// files) is dropped. The last line needs no '\n'.
class LineCursor {
 public:
  explicit LineCursor(std::string_view data) : data_(data) {}

  // Returns false at the end of the data.
  bool Next(std::string_view* line) {
    if (offset_ >= data_.size()) return false;
    size_t end = data_.find('\n', offset_);
    size_t next = end == std::string_view::npos ? data_.size() : end + 1;
    if (end == std::string_view::npos) end = data_.size();
    std::string_view result = data_.substr(offset_, end - offset_);
    if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
    *line = result;
    offset_ = next;
    ++line_number_;
    return true;
  }
  // 1-based number of the line last returned by Next().
  size_t line_number() const { return line_number_; }
  // Byte offset just after the line last returned (after its '\n').
  size_t offset() const { return offset_; }

 private:
  std::string_view data_;
  size_t offset_ = 0;
  size_t line_number_ = 0;
};

// Removes leading and trailing spaces, tabs and '\r'.
inline std::string_view Trim(std::string_view text) {
  const char* kSpace = " \t\r\f\v";
  const size_t begin = text.find_first_not_of(kSpace);
  if (begin == std::string_view::npos) return {};
  const size_t end = text.find_last_not_of(kSpace);
  return text.substr(begin, end - begin + 1);
}

// Splits on runs of whitespace, and also on commas when `commas` is true.
inline std::vector<std::string_view> SplitTokens(std::string_view text,
                                                 bool commas = false) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  auto is_separator = [commas](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' ||
           (commas && c == ',');
  };
  while (i < text.size()) {
    while (i < text.size() && is_separator(text[i])) ++i;
    const size_t begin = i;
    while (i < text.size() && !is_separator(text[i])) ++i;
    if (i > begin) tokens.push_back(text.substr(begin, i - begin));
  }
  return tokens;
}

// Parses a whole token as a double, independently of the C locale. Accepts a
// leading '+', exponents, and "nan" / "inf" (PCL writes "nan").
inline bool ParseDouble(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const std::from_chars_result result =
      std::from_chars(token.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

// Parses a whole token as a non-negative decimal integer.
inline bool ParseUint64(std::string_view token, uint64_t* value) {
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const std::from_chars_result result =
      std::from_chars(token.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

// ---- Byte helpers. ----------------------------------------------------------

// Loads an IEEE float (N = 4) or double (N = 8) stored with the given byte
// order, whatever the byte order of this machine.
inline double LoadFloat(const char* bytes, int size, bool big_endian) {
  uint64_t bits = 0;
  for (int i = 0; i < size; ++i) {
    const int index = big_endian ? i : size - 1 - i;
    bits = (bits << 8) | static_cast<unsigned char>(bytes[index]);
  }
  if (size == 4) {
    const uint32_t bits32 = static_cast<uint32_t>(bits);
    float value;
    std::memcpy(&value, &bits32, sizeof(value));
    return value;
  }
  double value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

// Loads an unsigned integer of `size` bytes (1, 2, 4 or 8).
inline uint64_t LoadUnsigned(const char* bytes, int size, bool big_endian) {
  uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    const int index = big_endian ? i : size - 1 - i;
    value = (value << 8) | static_cast<unsigned char>(bytes[index]);
  }
  return value;
}

// Appends `value` as a little-endian IEEE float32.
inline void AppendFloat32Le(float value, std::string* out) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  for (int i = 0; i < 4; ++i)
    out->push_back(static_cast<char>(bits >> (8 * i)));
}

// Sets *product = a * b; returns false when that overflows 64 bits.
inline bool MultiplyChecked(uint64_t a, uint64_t b, uint64_t* product) {
  return !__builtin_mul_overflow(a, b, product);
}

}  // namespace internal
}  // namespace mlndt
