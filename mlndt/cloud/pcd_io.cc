// PCD reading and writing (format summary in mlndt/cloud/io.h; the reference
// is PCL's pcd_io.cpp and the PCD file format page of pointclouds.org).

#include <lzf.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/common/internal/enum_strings.h"

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

// The header's lines as read, before their checks.
struct RawPcdHeader {
  std::vector<std::string> names, sizes, types, counts;
  bool have_fields = false, have_size = false, have_type = false;
  bool have_count = false, have_width = false;
  bool have_points = false, have_data = false;
  uint64_t width = 0, height = 1, points = 0;
};

// `line` with anything unprintable as '?', at most 40 characters.
std::string Printable(std::string_view line) {
  std::string shown(line.substr(0, 40));
  for (char& c : shown) {
    if (static_cast<unsigned char>(c) < 32 ||
        static_cast<unsigned char>(c) > 126)
      c = '?';
  }
  return shown;
}

bool ParseVersion(const std::vector<std::string_view>& tokens,
                  std::string_view line,
                  const std::string& line_tag,
                  std::string* error) {
  static const char* kVersions[] = {"0.7", ".7", "0.6", ".6", "0.5", ".5"};
  const bool known = tokens.size() == 2 &&
                     std::any_of(std::begin(kVersions),
                                 std::end(kVersions),
                                 [&](const char* v) { return tokens[1] == v; });
  if (!known) {
    *error = line_tag + ": unsupported VERSION '" + std::string(line) +
             "' (supported: 0.7, 0.6, 0.5)";
  }
  return known;
}

bool ParseDataKind(const std::vector<std::string_view>& tokens,
                   std::string_view line,
                   const std::string& line_tag,
                   PcdData* data,
                   std::string* error) {
  std::string kind = tokens.size() == 2 ? std::string(tokens[1]) : "";
  UpperCase(&kind);
  if (kind == "ASCII") {
    *data = PcdData::ASCII;
  } else if (kind == "BINARY") {
    *data = PcdData::BINARY;
  } else if (kind == "BINARY_COMPRESSED") {
    *data = PcdData::BINARY_COMPRESSED;
  } else {
    *error = line_tag + ": unsupported DATA '" + std::string(line) +
             "' (supported: ascii, binary, binary_compressed)";
    return false;
  }
  return true;
}

// One header line (not DATA) into `raw`; false with `error` on a bad one.
bool ParseHeaderLine(const std::string& keyword,
                     const std::vector<std::string_view>& tokens,
                     std::string_view line,
                     const std::string& line_tag,
                     RawPcdHeader* raw,
                     std::string* error) {
  auto values = [&tokens]() {
    return std::vector<std::string>(tokens.begin() + 1, tokens.end());
  };
  auto parse_count = [&](uint64_t* value, bool* have) {
    if (tokens.size() != 2 || !ParseUint64(tokens[1], value)) {
      *error = line_tag + ": " + keyword +
               " needs one non-negative integer, found '" + std::string(line) +
               "'";
      return false;
    }
    if (have != nullptr) *have = true;
    return true;
  };
  if (keyword == "VERSION") return ParseVersion(tokens, line, line_tag, error);
  if (keyword == "FIELDS" || keyword == "COLUMNS") {
    raw->names = values();
    raw->have_fields = true;
  } else if (keyword == "SIZE") {
    raw->sizes = values();
    raw->have_size = true;
  } else if (keyword == "TYPE") {
    raw->types = values();
    raw->have_type = true;
  } else if (keyword == "COUNT") {
    raw->counts = values();
    raw->have_count = true;
  } else if (keyword == "WIDTH") {
    return parse_count(&raw->width, &raw->have_width);
  } else if (keyword == "HEIGHT") {
    return parse_count(&raw->height, nullptr);
  } else if (keyword == "POINTS") {
    return parse_count(&raw->points, &raw->have_points);
  } else if (keyword != "VIEWPOINT") {
    // VIEWPOINT (the sensor pose) is not applied; PCL does not apply it
    // either. Also what a non-PCD file (bad magic) ends up here with.
    *error = "not a PCD header: unexpected " + line_tag + " '" +
             Printable(line) +
             "' (expected VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, "
             "VIEWPOINT, POINTS or DATA)";
    return false;
  }
  return true;
}

// Reads the header lines up to and including DATA.
bool ReadHeaderLines(const std::string& data,
                     RawPcdHeader* raw,
                     PcdHeader* header,
                     std::string* error) {
  LineCursor cursor(data);
  std::string_view raw_line;
  while (cursor.Next(&raw_line)) {
    const std::string_view line = Trim(raw_line);
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> tokens = SplitTokens(line);
    std::string keyword(tokens[0]);
    UpperCase(&keyword);
    const std::string line_tag =
        "header line " + std::to_string(cursor.line_number());
    if (keyword == "DATA") {
      if (!ParseDataKind(tokens, line, line_tag, &header->data, error)) {
        return false;
      }
      raw->have_data = true;
      header->body_offset = cursor.offset();
      return true;
    }
    if (!ParseHeaderLine(keyword, tokens, line, line_tag, raw, error)) {
      return false;
    }
  }
  *error = "not a PCD header: no DATA line";
  return false;
}

// FIELDS, SIZE, TYPE and COUNT are there and agree in length.
bool CheckFieldLines(RawPcdHeader* raw, std::string* error) {
  if (!raw->have_fields || !raw->have_size || !raw->have_type) {
    *error = std::string("bad header: missing ") +
             (!raw->have_fields ? "FIELDS"
              : !raw->have_size ? "SIZE"
                                : "TYPE") +
             " line";
    return false;
  }
  if (raw->names.empty()) {
    *error = "bad header: FIELDS is empty";
    return false;
  }
  if (!raw->have_count) raw->counts.assign(raw->names.size(), "1");
  if (raw->sizes.size() != raw->names.size() ||
      raw->types.size() != raw->names.size() ||
      raw->counts.size() != raw->names.size()) {
    *error = "bad header: FIELDS has " + std::to_string(raw->names.size()) +
             " entries but SIZE has " + std::to_string(raw->sizes.size()) +
             ", TYPE " + std::to_string(raw->types.size()) + " and COUNT " +
             std::to_string(raw->counts.size());
    return false;
  }
  return true;
}

// Field i of `raw`, its type, size and count checked.
bool MakeField(const RawPcdHeader& raw,
               size_t i,
               PcdField* field,
               std::string* error) {
  field->name = raw.names[i];
  field->type = raw.types[i];
  UpperCase(&field->type);
  if (field->type != "F" && field->type != "I" && field->type != "U") {
    *error = "unsupported TYPE '" + raw.types[i] + "' for field " +
             field->name + " (PCD types are F, I and U)";
    return false;
  }
  if (!ParseUint64(raw.sizes[i], &field->size) || field->size == 0) {
    *error = "unsupported SIZE '" + raw.sizes[i] + "' for field " + field->name;
    return false;
  }
  if (!ParseUint64(raw.counts[i], &field->count) || field->count == 0) {
    *error = "bad header: COUNT '" + raw.counts[i] + "' for field " +
             field->name + " is not a positive integer";
    return false;
  }
  return true;
}

// Fields and the record layout.
bool BuildFields(const RawPcdHeader& raw,
                 PcdHeader* header,
                 std::string* error) {
  uint64_t offset = 0;
  for (size_t i = 0; i < raw.names.size(); ++i) {
    PcdField field;
    if (!MakeField(raw, i, &field, error)) return false;
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
  return true;
}

// x, y and z are there, each one float or double.
bool CheckXyzFields(const PcdHeader& header, std::string* error) {
  std::string missing;
  for (int axis = 0; axis < 3; ++axis) {
    if (header.xyz[axis] < 0)
      missing += std::string(missing.empty() ? "" : ", ") + "xyz"[axis];
  }
  if (!missing.empty()) {
    *error = "missing field " + missing +
             " (FIELDS are: " + Join(header.fields) +
             "; x, y and z are required)";
    return false;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const PcdField& field = header.fields[header.xyz[axis]];
    if (field.type != "F" || (field.size != 4 && field.size != 8) ||
        field.count != 1) {
      *error = "unsupported TYPE/SIZE for field " + field.name + ": TYPE " +
               field.type + " SIZE " + std::to_string(field.size) + " COUNT " +
               std::to_string(field.count) +
               " (x, y and z must be TYPE F with SIZE 4 or 8 and COUNT 1)";
      return false;
    }
  }
  return true;
}

// Point count: POINTS and WIDTH*HEIGHT must agree (either may be missing).
bool ResolvePointCount(const RawPcdHeader& raw,
                       PcdHeader* header,
                       std::string* error) {
  if (!raw.have_width && !raw.have_points) {
    *error = "bad header: neither WIDTH nor POINTS is given";
    return false;
  }
  uint64_t points = raw.points;
  if (raw.have_width) {
    uint64_t product;
    if (!MultiplyChecked(raw.width, raw.height, &product)) {
      *error = "count mismatch: WIDTH*HEIGHT overflows";
      return false;
    }
    if (raw.have_points && product != raw.points) {
      *error = "header/count mismatch: POINTS is " +
               std::to_string(raw.points) + " but WIDTH*HEIGHT is " +
               std::to_string(raw.width) + "*" + std::to_string(raw.height) +
               " = " + std::to_string(product);
      return false;
    }
    points = product;
  }
  header->points = points;
  return true;
}

// Reads the header lines up to and including DATA, then checks them.
bool ParseHeader(const std::string& data,
                 PcdHeader* header,
                 std::string* error) {
  if (data.empty()) {
    *error = "empty file (not a PCD file)";
    return false;
  }
  RawPcdHeader raw;
  return ReadHeaderLines(data, &raw, header, error) &&
         CheckFieldLines(&raw, error) && BuildFields(raw, header, error) &&
         CheckXyzFields(*header, error) &&
         ResolvePointCount(raw, header, error);
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
