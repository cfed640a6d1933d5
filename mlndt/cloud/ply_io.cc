// PLY reading and writing (format summary in mlndt/cloud/io.h; the reference
// is Greg Turk's PLY 1.0 description, as in paulbourke.net/dataformats/ply).
//
// Header: "ply", "format <ascii|binary_little_endian|binary_big_endian> 1.0",
// then "element <name> <count>" each followed by its "property <type> <name>"
// or "property list <count type> <item type> <name>" lines, "comment" and
// "obj_info" lines anywhere, and "end_header". The body stores the elements
// in header order: ascii has one line per element instance, binary packs the
// properties of each instance back to back (a list is its count followed by
// that many items).

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"

namespace mlndt {
namespace internal {
namespace {

enum class PlyFormat { ASCII, BINARY_LITTLE_ENDIAN, BINARY_BIG_ENDIAN };

struct PlyProperty {
  std::string name;
  std::string type;  // As written (item type for lists).
  int size = 0;      // Bytes per value (item size for lists).
  bool is_float = false;
  bool is_list = false;
  int count_size = 0;  // Bytes of a list's count.
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

// Size in bytes of a PLY scalar type name (both the classic and the sized
// spellings), 0 for an unknown name.
int ScalarSize(std::string_view type, bool* is_float) {
  *is_float = type == "float" || type == "float32" || type == "double" ||
              type == "float64";
  if (type == "char" || type == "int8" || type == "uchar" || type == "uint8")
    return 1;
  if (type == "short" || type == "int16" || type == "ushort" ||
      type == "uint16")
    return 2;
  if (type == "int" || type == "int32" || type == "uint" || type == "uint32")
    return 4;
  if (type == "float" || type == "float32") return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// "format <kind> 1.0".
bool ParseFormatLine(const std::vector<std::string_view>& tokens,
                     std::string_view line,
                     const std::string& line_tag,
                     PlyFormat* format,
                     std::string* error) {
  const bool known_version =
      tokens.size() == 3 && (tokens[2] == "1.0" || tokens[2] == "1");
  if (known_version && tokens[1] == "ascii") {
    *format = PlyFormat::ASCII;
  } else if (known_version && tokens[1] == "binary_little_endian") {
    *format = PlyFormat::BINARY_LITTLE_ENDIAN;
  } else if (known_version && tokens[1] == "binary_big_endian") {
    *format = PlyFormat::BINARY_BIG_ENDIAN;
  } else {
    *error = line_tag + ": bad format line '" + std::string(line) +
             "' (expected 'format "
             "ascii|binary_little_endian|binary_big_endian 1.0')";
    return false;
  }
  return true;
}

// "property <type> <name>" or "property list <count type> <type> <name>".
bool ParsePropertyLine(const std::vector<std::string_view>& tokens,
                       std::string_view line,
                       const std::string& line_tag,
                       PlyProperty* property,
                       std::string* error) {
  bool count_is_float = false;
  if (tokens.size() == 5 && tokens[1] == "list") {
    property->is_list = true;
    property->count_size = ScalarSize(tokens[2], &count_is_float);
    property->type = std::string(tokens[3]);
    property->size = ScalarSize(tokens[3], &property->is_float);
    property->name = std::string(tokens[4]);
  } else if (tokens.size() == 3) {
    property->type = std::string(tokens[1]);
    property->size = ScalarSize(tokens[1], &property->is_float);
    property->name = std::string(tokens[2]);
  } else {
    *error = line_tag + ": bad property line '" + std::string(line) + "'";
    return false;
  }
  if (property->size == 0 ||
      (property->is_list && (property->count_size == 0 || count_is_float))) {
    *error =
        line_tag + ": unknown property type in '" + std::string(line) + "'";
    return false;
  }
  return true;
}

bool ParseHeader(const std::string& data,
                 PlyFormat* format,
                 std::vector<PlyElement>* elements,
                 LineCursor* cursor,
                 std::string* error) {
  if (data.empty()) {
    *error = "empty file (not a PLY file)";
    return false;
  }
  std::string_view line;
  if (!cursor->Next(&line) || Trim(line) != "ply") {
    *error = "not a PLY file: the first line is not 'ply'";
    return false;
  }
  bool have_format = false;
  while (cursor->Next(&line)) {
    line = Trim(line);
    const std::string line_tag =
        "header line " + std::to_string(cursor->line_number());
    const std::vector<std::string_view> tokens = SplitTokens(line);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!have_format) {
        *error = "bad header: no format line";
        return false;
      }
      return true;
    }
    if (keyword == "format") {
      if (!ParseFormatLine(tokens, line, line_tag, format, error)) return false;
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      if (tokens.size() != 3 || !ParseUint64(tokens[2], &element.count)) {
        *error = line_tag + ": bad element line '" + std::string(line) + "'";
        return false;
      }
      element.name = std::string(tokens[1]);
      elements->push_back(element);
    } else if (keyword == "property") {
      if (elements->empty()) {
        *error = line_tag + ": property before any element line";
        return false;
      }
      PlyProperty property;
      if (!ParsePropertyLine(tokens, line, line_tag, &property, error)) {
        return false;
      }
      elements->back().properties.push_back(property);
    } else {
      *error = line_tag + ": unexpected header line '" +
               std::string(line.substr(0, 40)) + "'";
      return false;
    }
  }
  *error = "bad header: no end_header line";
  return false;
}

// Skips the ascii lines (one per instance) of an element before the vertices.
bool SkipAsciiElement(const PlyElement& element,
                      LineCursor* cursor,
                      std::string* error) {
  uint64_t skipped = 0;
  std::string_view line;
  while (skipped < element.count) {
    if (!cursor->Next(&line)) {
      *error = "truncated ascii body: expected " +
               std::to_string(element.count) + " '" + element.name +
               "' lines, found " + std::to_string(skipped);
      return false;
    }
    if (!Trim(line).empty()) ++skipped;
  }
  return true;
}

// Skips the binary instances of an element before the vertices.
bool SkipBinaryElement(const PlyElement& element,
                       const std::string& data,
                       bool big_endian,
                       size_t* offset,
                       std::string* error) {
  const uint64_t available = data.size() - *offset;
  const bool has_lists =
      std::any_of(element.properties.begin(),
                  element.properties.end(),
                  [](const PlyProperty& p) { return p.is_list; });
  auto truncated = [&]() {
    *error = "truncated binary body: element '" + element.name +
             "' runs past the end of the file";
    return false;
  };
  if (!has_lists) {
    uint64_t stride = 0, total;
    for (const PlyProperty& p : element.properties) stride += p.size;
    if (!MultiplyChecked(stride, element.count, &total) || total > available)
      return truncated();
    *offset += total;
    return true;
  }
  // Every instance takes at least one byte (a list count), so this loop is
  // bounded by the file size even for an absurd count.
  for (uint64_t i = 0; i < element.count; ++i) {
    for (const PlyProperty& p : element.properties) {
      uint64_t bytes = p.size;
      if (p.is_list) {
        if (data.size() - *offset < static_cast<uint64_t>(p.count_size))
          return truncated();
        const uint64_t items =
            LoadUnsigned(data.data() + *offset, p.count_size, big_endian);
        *offset += p.count_size;
        bytes = items * p.size;  // Count is at most 2^32-1, size at most 8.
      }
      if (data.size() - *offset < bytes) return truncated();
      *offset += bytes;
    }
  }
  return true;
}

// Where x, y and z sit in a vertex record.
struct VertexLayout {
  int xyz[3] = {-1, -1, -1};           // Property index of x, y, z.
  uint64_t xyz_offset[3] = {0, 0, 0};  // Byte offset in a binary record.
  uint64_t stride = 0;                 // Bytes per binary record.
};

bool FindVertexLayout(const PlyElement& vertex,
                      VertexLayout* layout,
                      std::string* error) {
  for (size_t i = 0; i < vertex.properties.size(); ++i) {
    const PlyProperty& property = vertex.properties[i];
    if (property.is_list) {
      *error = "unsupported list property '" + property.name +
               "' in the vertex element";
      return false;
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (property.name == std::string(1, "xyz"[axis]) &&
          layout->xyz[axis] < 0) {
        if (!property.is_float) {
          *error = "unsupported type '" + property.type +
                   "' for vertex property " + property.name +
                   " (x, y and z must be float/float32 or double/float64)";
          return false;
        }
        layout->xyz[axis] = static_cast<int>(i);
        layout->xyz_offset[axis] = layout->stride;
      }
    }
    layout->stride += property.size;
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (layout->xyz[axis] < 0) {
      *error = std::string("missing field ") + "xyz"[axis] +
               ": the vertex element needs properties x, y and z";
      return false;
    }
  }
  return true;
}

// The vertex lines of an ascii body, the cursor at the first one.
bool ReadAsciiVertices(const std::string& data,
                       const PlyElement& vertex,
                       const VertexLayout& layout,
                       LineCursor* cursor,
                       std::vector<Eigen::Vector3d>* points,
                       std::string* error) {
  // At least 6 bytes per vertex line ("0 0 0\n") bound the reserve.
  points->reserve(std::min<uint64_t>(vertex.count,
                                     (data.size() - cursor->offset()) / 6 + 1));
  std::string_view line;
  uint64_t found = 0;
  while (found < vertex.count) {
    if (!cursor->Next(&line)) {
      *error = "truncated ascii body: expected " +
               std::to_string(vertex.count) + " vertices, found " +
               std::to_string(found);
      return false;
    }
    line = Trim(line);
    if (line.empty()) continue;
    const std::string line_tag =
        "line " + std::to_string(cursor->line_number());
    const std::vector<std::string_view> tokens = SplitTokens(line);
    if (tokens.size() < vertex.properties.size()) {
      *error = line_tag + ": cannot parse vertex: expected " +
               std::to_string(vertex.properties.size()) + " values, found " +
               std::to_string(tokens.size());
      return false;
    }
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = tokens[layout.xyz[axis]];
      if (!ParseDouble(token, &point[axis])) {
        *error = line_tag + ": cannot parse " + std::string(1, "xyz"[axis]) +
                 " value '" + std::string(token) + "'";
        return false;
      }
    }
    points->push_back(point);
    ++found;
  }
  return true;
}

// The vertex records of a binary body from byte `offset` on.
bool ReadBinaryVertices(const std::string& data,
                        const PlyElement& vertex,
                        const VertexLayout& layout,
                        bool big_endian,
                        size_t offset,
                        std::vector<Eigen::Vector3d>* points,
                        std::string* error) {
  const uint64_t available = data.size() - offset;
  uint64_t expected;
  const bool overflow =
      !MultiplyChecked(vertex.count, layout.stride, &expected);
  if (overflow || expected > available) {
    *error = "truncated binary body: expected " +
             (overflow ? std::to_string(vertex.count) + " vertices of " +
                             std::to_string(layout.stride) + " bytes"
                       : std::to_string(expected) + " bytes") +
             ", found " + std::to_string(available);
    return false;
  }
  points->reserve(vertex.count);
  const char* record = data.data() + offset;
  for (uint64_t i = 0; i < vertex.count; ++i, record += layout.stride) {
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis) {
      point[axis] = LoadFloat(record + layout.xyz_offset[axis],
                              vertex.properties[layout.xyz[axis]].size,
                              big_endian);
    }
    points->push_back(point);
  }
  return true;
}

}  // namespace

bool ParsePly(const std::string& data,
              std::vector<Eigen::Vector3d>* points,
              std::string* error) {
  PlyFormat format = PlyFormat::ASCII;
  std::vector<PlyElement> elements;
  LineCursor cursor(data);
  if (!ParseHeader(data, &format, &elements, &cursor, error)) return false;

  const auto vertex_it =
      std::find_if(elements.begin(), elements.end(), [](const PlyElement& e) {
        return e.name == "vertex";
      });
  if (vertex_it == elements.end()) {
    *error = "no vertex element in the header";
    return false;
  }
  VertexLayout layout;
  if (!FindVertexLayout(*vertex_it, &layout, error)) return false;

  if (format == PlyFormat::ASCII) {
    for (auto it = elements.begin(); it != vertex_it; ++it) {
      if (!SkipAsciiElement(*it, &cursor, error)) return false;
    }
    return ReadAsciiVertices(data, *vertex_it, layout, &cursor, points, error);
  }
  const bool big_endian = format == PlyFormat::BINARY_BIG_ENDIAN;
  size_t offset = cursor.offset();
  for (auto it = elements.begin(); it != vertex_it; ++it) {
    if (!SkipBinaryElement(*it, data, big_endian, &offset, error)) return false;
  }
  return ReadBinaryVertices(
      data, *vertex_it, layout, big_endian, offset, points, error);
}

std::string EncodePlyBinary(const PointCloud& cloud) {
  std::string out =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment written by mlndt\n"
      "element vertex " +
      std::to_string(cloud.size()) +
      "\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "end_header\n";
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
