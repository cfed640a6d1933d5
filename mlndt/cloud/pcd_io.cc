// PCD reading and writing (format summary in mlndt/cloud/io.h; the reference
// is PCL's pcd_io.cpp and the PCD file format page of pointclouds.org).

#include <lzf.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/common/internal/enum_strings.h"
#include "mlndt/internal/cloud_readers.h"

namespace mlndt {
namespace internal {
namespace {

// One entry of FIELDS with its SIZE, TYPE and COUNT.
struct PcdField {
  std::string name;
  std::string type;     // "F", "I" or "U".
  uint64_t size = 0;    // Bytes per value.
  uint64_t count = 1;   // Values per point.
  uint64_t offset = 0;  // Byte offset inside a binary record.
};

enum class PcdData { ASCII, BINARY, BINARY_COMPRESSED };

struct PcdHeader {
  std::vector<PcdField> fields;
  uint64_t points = 0;
  PcdData data = PcdData::ASCII;
  uint64_t point_size = 0;    // Bytes per binary record.
  int xyz[3] = {-1, -1, -1};  // Index into `fields` of x, y, z.
  size_t body_offset = 0;     // First byte after the DATA line.
};

std::string Join(const std::vector<PcdField>& fields) {
  std::string names;
  for (const PcdField& field : fields) {
    if (!names.empty()) names += " ";
    names += field.name;
  }
  return names;
}

// Reads the header lines up to and including DATA, then checks them.
bool ParseHeader(const std::string& data,
                 PcdHeader* header,
                 std::string* error) {
  if (data.empty()) {
    *error = "empty file (not a PCD file)";
    return false;
  }
  LineCursor cursor(data);
  std::string_view raw_line;
  std::vector<std::string> names, sizes, types, counts;
  bool have_fields = false, have_size = false, have_type = false;
  bool have_count = false, have_width = false;
  bool have_points = false, have_data = false;
  uint64_t width = 0, height = 1, points = 0;
  while (cursor.Next(&raw_line)) {
    const std::string_view line = Trim(raw_line);
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> tokens = SplitTokens(line);
    std::string keyword(tokens[0]);
    UpperCase(&keyword);
    const std::string line_tag =
        "header line " + std::to_string(cursor.line_number());
    auto values = [&tokens]() {
      return std::vector<std::string>(tokens.begin() + 1, tokens.end());
    };
    auto parse_count = [&](uint64_t* value) {
      if (tokens.size() != 2 || !ParseUint64(tokens[1], value)) {
        *error = line_tag + ": " + keyword +
                 " needs one non-negative integer, found '" +
                 std::string(line) + "'";
        return false;
      }
      return true;
    };
    if (keyword == "VERSION") {
      static const char* kVersions[] = {"0.7", ".7", "0.6", ".6", "0.5", ".5"};
      const bool known =
          tokens.size() == 2 &&
          std::any_of(std::begin(kVersions),
                      std::end(kVersions),
                      [&](const char* v) { return tokens[1] == v; });
      if (!known) {
        *error = line_tag + ": unsupported VERSION '" + std::string(line) +
                 "' (supported: 0.7, 0.6, 0.5)";
        return false;
      }
    } else if (keyword == "FIELDS" || keyword == "COLUMNS") {
      names = values();
      have_fields = true;
    } else if (keyword == "SIZE") {
      sizes = values();
      have_size = true;
    } else if (keyword == "TYPE") {
      types = values();
      have_type = true;
    } else if (keyword == "COUNT") {
      counts = values();
      have_count = true;
    } else if (keyword == "WIDTH") {
      if (!parse_count(&width)) return false;
      have_width = true;
    } else if (keyword == "HEIGHT") {
      if (!parse_count(&height)) return false;
    } else if (keyword == "POINTS") {
      if (!parse_count(&points)) return false;
      have_points = true;
    } else if (keyword == "VIEWPOINT") {
      // Sensor pose; not applied (PCL does not apply it either).
    } else if (keyword == "DATA") {
      std::string kind = tokens.size() == 2 ? std::string(tokens[1]) : "";
      UpperCase(&kind);
      if (kind == "ASCII") {
        header->data = PcdData::ASCII;
      } else if (kind == "BINARY") {
        header->data = PcdData::BINARY;
      } else if (kind == "BINARY_COMPRESSED") {
        header->data = PcdData::BINARY_COMPRESSED;
      } else {
        *error = line_tag + ": unsupported DATA '" + std::string(line) +
                 "' (supported: ascii, binary, binary_compressed)";
        return false;
      }
      have_data = true;
      header->body_offset = cursor.offset();
      break;
    } else {
      // Also what a non-PCD file (bad magic) ends up here with.
      std::string shown(line.substr(0, 40));
      for (char& c : shown) {
        if (static_cast<unsigned char>(c) < 32 ||
            static_cast<unsigned char>(c) > 126)
          c = '?';
      }
      *error = "not a PCD header: unexpected " + line_tag + " '" + shown +
               "' (expected VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, "
               "VIEWPOINT, POINTS or DATA)";
      return false;
    }
  }
  if (!have_data) {
    *error = "not a PCD header: no DATA line";
    return false;
  }
  if (!have_fields || !have_size || !have_type) {
    *error = std::string("bad header: missing ") +
             (!have_fields ? "FIELDS"
              : !have_size ? "SIZE"
                           : "TYPE") +
             " line";
    return false;
  }
  if (names.empty()) {
    *error = "bad header: FIELDS is empty";
    return false;
  }
  if (!have_count) counts.assign(names.size(), "1");
  if (sizes.size() != names.size() || types.size() != names.size() ||
      counts.size() != names.size()) {
    *error = "bad header: FIELDS has " + std::to_string(names.size()) +
             " entries but SIZE has " + std::to_string(sizes.size()) +
             ", TYPE " + std::to_string(types.size()) + " and COUNT " +
             std::to_string(counts.size());
    return false;
  }

  // Fields, record layout and the x/y/z checks.
  uint64_t offset = 0;
  for (size_t i = 0; i < names.size(); ++i) {
    PcdField field;
    field.name = names[i];
    field.type = types[i];
    UpperCase(&field.type);
    if (field.type != "F" && field.type != "I" && field.type != "U") {
      *error = "unsupported TYPE '" + types[i] + "' for field " + field.name +
               " (PCD types are F, I and U)";
      return false;
    }
    if (!ParseUint64(sizes[i], &field.size) || field.size == 0) {
      *error = "unsupported SIZE '" + sizes[i] + "' for field " + field.name;
      return false;
    }
    if (!ParseUint64(counts[i], &field.count) || field.count == 0) {
      *error = "bad header: COUNT '" + counts[i] + "' for field " + field.name +
               " is not a positive integer";
      return false;
    }
    field.offset = offset;
    uint64_t field_bytes;
    if (!MultiplyChecked(field.size, field.count, &field_bytes) ||
        offset + field_bytes < offset) {
      *error = "bad header: absurd SIZE*COUNT for field " + field.name;
      return false;
    }
    offset += field_bytes;
    for (int axis = 0; axis < 3; ++axis) {
      if (field.name == std::string(1, "xyz"[axis]) && header->xyz[axis] < 0) {
        header->xyz[axis] = static_cast<int>(i);
      }
    }
    header->fields.push_back(field);
  }
  header->point_size = offset;
  std::string missing;
  for (int axis = 0; axis < 3; ++axis) {
    if (header->xyz[axis] < 0)
      missing += std::string(missing.empty() ? "" : ", ") + "xyz"[axis];
  }
  if (!missing.empty()) {
    *error = "missing field " + missing +
             " (FIELDS are: " + Join(header->fields) +
             "; x, y and z are required)";
    return false;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const PcdField& field = header->fields[header->xyz[axis]];
    if (field.type != "F" || (field.size != 4 && field.size != 8) ||
        field.count != 1) {
      *error = "unsupported TYPE/SIZE for field " + field.name + ": TYPE " +
               field.type + " SIZE " + std::to_string(field.size) + " COUNT " +
               std::to_string(field.count) +
               " (x, y and z must be TYPE F with SIZE 4 or 8 and COUNT 1)";
      return false;
    }
  }

  // Point count: POINTS and WIDTH*HEIGHT must agree (either may be missing).
  if (!have_width && !have_points) {
    *error = "bad header: neither WIDTH nor POINTS is given";
    return false;
  }
  if (have_width) {
    uint64_t product;
    if (!MultiplyChecked(width, height, &product)) {
      *error = "count mismatch: WIDTH*HEIGHT overflows";
      return false;
    }
    if (have_points && product != points) {
      *error = "header/count mismatch: POINTS is " + std::to_string(points) +
               " but WIDTH*HEIGHT is " + std::to_string(width) + "*" +
               std::to_string(height) + " = " + std::to_string(product);
      return false;
    }
    points = product;
  }
  header->points = points;
  return true;
}

bool ParseAsciiBody(const std::string& data,
                    const PcdHeader& header,
                    std::vector<Eigen::Vector3d>* points,
                    std::string* error) {
  // Token position of x, y, z in a line. PCL's ascii writer writes no values
  // for '_' padding fields while its reader expects COUNT of them, so both
  // layouts are accepted, told apart by the number of values.
  uint64_t with_padding = 0, without_padding = 0;
  uint64_t column_with[3] = {0, 0, 0}, column_without[3] = {0, 0, 0};
  for (size_t i = 0; i < header.fields.size(); ++i) {
    const PcdField& field = header.fields[i];
    for (int axis = 0; axis < 3; ++axis) {
      if (header.xyz[axis] == static_cast<int>(i)) {
        column_with[axis] = with_padding;
        column_without[axis] = without_padding;
      }
    }
    with_padding += field.count;
    if (field.name != "_") without_padding += field.count;
  }

  std::string_view body(data);
  body.remove_prefix(header.body_offset);
  // Every ascii point takes at least 6 bytes ("0 0 0\n"), so this reserve
  // cannot be driven beyond the file size by an absurd POINTS.
  points->reserve(std::min<uint64_t>(header.points, body.size() / 6 + 1));
  // Line numbers in messages count from the top of the file.
  LineCursor cursor(data);
  std::string_view line;
  while (cursor.offset() < header.body_offset && cursor.Next(&line)) {
  }
  uint64_t found = 0;
  while (cursor.Next(&line)) {
    line = Trim(line);
    if (line.empty()) continue;
    const std::string line_tag = "line " + std::to_string(cursor.line_number());
    if (found == header.points) {
      *error = "header/count mismatch: POINTS is " +
               std::to_string(header.points) +
               " but the ascii body has more points (" + line_tag + ")";
      return false;
    }
    const std::vector<std::string_view> tokens = SplitTokens(line);
    const uint64_t* column = nullptr;
    if (tokens.size() == with_padding) {
      column = column_with;
    } else if (tokens.size() == without_padding) {
      column = column_without;
    } else {
      *error = line_tag + ": cannot parse point: expected " +
               std::to_string(with_padding) + " values (FIELDS " +
               Join(header.fields) + "), found " +
               std::to_string(tokens.size());
      return false;
    }
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis) {
      if (!ParseDouble(tokens[column[axis]], &point[axis])) {
        *error = line_tag + ": cannot parse " + std::string(1, "xyz"[axis]) +
                 " value '" + std::string(tokens[column[axis]]) + "'";
        return false;
      }
    }
    points->push_back(point);
    ++found;
  }
  if (found < header.points) {
    *error = "header/count mismatch: POINTS is " +
             std::to_string(header.points) + " but the ascii body has only " +
             std::to_string(found) + " lines of points";
    return false;
  }
  return true;
}

bool ParseBinaryBody(const std::string& data,
                     const PcdHeader& header,
                     std::vector<Eigen::Vector3d>* points,
                     std::string* error) {
  const uint64_t available = data.size() - header.body_offset;
  uint64_t expected;
  const bool overflow =
      !MultiplyChecked(header.points, header.point_size, &expected);
  if (overflow || expected > available) {
    *error = "truncated binary body: expected " +
             (overflow ? std::to_string(header.points) + " points of " +
                             std::to_string(header.point_size) + " bytes"
                       : std::to_string(expected) + " bytes") +
             ", found " + std::to_string(available);
    return false;
  }
  const char* record = data.data() + header.body_offset;
  points->reserve(header.points);
  for (uint64_t i = 0; i < header.points; ++i, record += header.point_size) {
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis) {
      const PcdField& field = header.fields[header.xyz[axis]];
      point[axis] = LoadFloat(record + field.offset,
                              static_cast<int>(field.size),
                              /*big_endian=*/false);
    }
    points->push_back(point);
  }
  return true;
}

bool ParseCompressedBody(const std::string& data,
                         const PcdHeader& header,
                         std::vector<Eigen::Vector3d>* points,
                         std::string* error) {
  const uint64_t available = data.size() - header.body_offset;
  const char* body = data.data() + header.body_offset;
  if (available < 8) {
    *error =
        "corrupt binary_compressed body: expected 8 bytes of sizes, found " +
        std::to_string(available);
    return false;
  }
  const uint64_t compressed_size = LoadUnsigned(body, 4, /*big_endian=*/false);
  const uint64_t uncompressed_size =
      LoadUnsigned(body + 4, 4, /*big_endian=*/false);
  uint64_t expected;
  if (!MultiplyChecked(header.points, header.point_size, &expected) ||
      expected != uncompressed_size) {
    *error =
        "corrupt binary_compressed body: uncompressed size " +
        std::to_string(uncompressed_size) +
        " does not match POINTS*point size = " + std::to_string(header.points) +
        "*" + std::to_string(header.point_size);
    return false;
  }
  if (compressed_size > available - 8) {
    *error = "corrupt binary_compressed body: compressed size " +
             std::to_string(compressed_size) + " but only " +
             std::to_string(available - 8) + " bytes follow";
    return false;
  }
  if (header.points == 0) return true;
  // An LZF back reference emits at most 264 bytes from 3 input bytes, so
  // honest data never expands by more than 88x; this bounds the allocation.
  if (compressed_size == 0 || uncompressed_size > compressed_size * 88 + 64) {
    *error =
        "corrupt binary_compressed body: " + std::to_string(compressed_size) +
        " compressed bytes cannot hold " + std::to_string(uncompressed_size) +
        " bytes";
    return false;
  }
  std::vector<char> unpacked(uncompressed_size);
  const unsigned int produced =
      lzf_decompress(body + 8,
                     static_cast<unsigned int>(compressed_size),
                     unpacked.data(),
                     static_cast<unsigned int>(uncompressed_size));
  if (produced != uncompressed_size) {
    *error = "corrupt binary_compressed body: LZF decompression failed (got " +
             std::to_string(produced) + " of " +
             std::to_string(uncompressed_size) + " bytes)";
    return false;
  }
  // Field-major layout: field f occupies POINTS*SIZE*COUNT bytes starting at
  // POINTS*offset(f), so point i's x is at POINTS*offset(x) + i*SIZE(x).
  points->reserve(header.points);
  for (uint64_t i = 0; i < header.points; ++i) {
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis) {
      const PcdField& field = header.fields[header.xyz[axis]];
      const char* value =
          unpacked.data() + header.points * field.offset + i * field.size;
      point[axis] =
          LoadFloat(value, static_cast<int>(field.size), /*big_endian=*/false);
    }
    points->push_back(point);
  }
  return true;
}

}  // namespace

bool ParsePcd(const std::string& data,
              std::vector<Eigen::Vector3d>* points,
              std::string* error) {
  PcdHeader header;
  if (!ParseHeader(data, &header, error)) return false;
  switch (header.data) {
    case PcdData::ASCII:
      return ParseAsciiBody(data, header, points, error);
    case PcdData::BINARY:
      return ParseBinaryBody(data, header, points, error);
    case PcdData::BINARY_COMPRESSED:
      return ParseCompressedBody(data, header, points, error);
  }
  return false;
}

std::string EncodePcdBinary(const PointCloud& cloud) {
  const std::string count = std::to_string(cloud.size());
  std::string out =
      "# .PCD v0.7 - Point Cloud Data file format\n"
      "VERSION 0.7\n"
      "FIELDS x y z\n"
      "SIZE 4 4 4\n"
      "TYPE F F F\n"
      "COUNT 1 1 1\n"
      "WIDTH " +
      count +
      "\n"
      "HEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\n"
      "POINTS " +
      count +
      "\n"
      "DATA binary\n";
  out.reserve(out.size() + 12 * cloud.size());
  for (const Eigen::Vector3d& p : cloud.points()) {
    for (int axis = 0; axis < 3; ++axis) {
      AppendFloat32Le(static_cast<float>(p[axis]), &out);
    }
  }
  return out;
}

}  // namespace internal
}  // namespace mlndt
