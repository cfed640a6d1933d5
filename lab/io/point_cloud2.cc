#include "lab/io/point_cloud2.h"

#include <cmath>
#include <cstring>
#include <utility>

namespace mlndt {
namespace {

// Where a field is and how to read it.
struct FieldReader {
  bool found = false;
  uint32_t offset = 0;
  uint8_t datatype = 0;
};

FieldReader FindField(const PointCloud2View& message, const std::string& name) {
  FieldReader reader;
  for (const PointCloud2Field& field : message.fields) {
    if (field.name == name) {
      reader.found = true;
      reader.offset = field.offset;
      reader.datatype = field.datatype;
    }
  }
  return reader;
}

size_t DatatypeSize(uint8_t datatype) {
  switch (datatype) {
    case kPointFieldInt8:
    case kPointFieldUint8:
      return 1;
    case kPointFieldInt16:
    case kPointFieldUint16:
      return 2;
    case kPointFieldInt32:
    case kPointFieldUint32:
    case kPointFieldFloat32:
      return 4;
    case kPointFieldFloat64:
      return 8;
  }
  return 0;
}

// The value of a field of the point at `data` as a double (little-endian
// host; big-endian messages are refused before).
double ReadValue(const uint8_t* data, const FieldReader& field) {
  const uint8_t* p = data + field.offset;
  switch (field.datatype) {
    case kPointFieldFloat32: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case kPointFieldFloat64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
    case kPointFieldUint32: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case kPointFieldInt32: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
  return NAN;
}

// The per-point time field and the factor to seconds, if the message has
// one of the known ones.
FieldReader FindTimeField(const PointCloud2View& message,
                          std::string* name,
                          double* to_seconds) {
  for (const char* candidate : {"time", "t", "offset_time", "timestamp"}) {
    FieldReader field = FindField(message, candidate);
    if (!field.found) continue;
    const bool is_float = field.datatype == kPointFieldFloat32 ||
                          field.datatype == kPointFieldFloat64;
    const bool is_int = field.datatype == kPointFieldUint32 ||
                        field.datatype == kPointFieldInt32;
    if (!is_float && !is_int) continue;
    *name = candidate;
    *to_seconds = is_float ? 1.0 : 1e-9;
    return field;
  }
  return FieldReader();
}

bool CheckLayout(const PointCloud2View& message,
                 const std::vector<FieldReader>& fields,
                 std::string* error) {
  if (message.is_bigendian) {
    *error = "big-endian point data is not supported";
    return false;
  }
  for (const FieldReader& field : fields) {
    const size_t size = DatatypeSize(field.datatype);
    if (size == 0 || field.offset + size > message.point_step) {
      *error = "a field lies outside point_step " +
               std::to_string(message.point_step);
      return false;
    }
  }
  const uint64_t row = uint64_t{message.width} * message.point_step;
  if (message.row_step < row) {
    *error = "row_step " + std::to_string(message.row_step) +
             " is less than width x point_step (" +
             std::to_string(message.width) + " x " +
             std::to_string(message.point_step) + " = " + std::to_string(row) +
             ")";
    return false;
  }
  if (uint64_t{message.row_step} * message.height > message.data_size) {
    *error = "data holds " + std::to_string(message.data_size) +
             " bytes, fewer than height x row_step (" +
             std::to_string(message.height) + " x " +
             std::to_string(message.row_step) + ")";
    return false;
  }
  return true;
}

}  // namespace

bool DecodePointCloud2(const PointCloud2View& message,
                       PointCloud2Scan* scan,
                       std::string* error) {
  const FieldReader x = FindField(message, "x"), y = FindField(message, "y"),
                    z = FindField(message, "z");
  for (const FieldReader* f : {&x, &y, &z}) {
    if (!f->found || (f->datatype != kPointFieldFloat32 &&
                      f->datatype != kPointFieldFloat64)) {
      *error = "no float32/float64 x, y and z fields";
      return false;
    }
  }
  double to_seconds = 1.0;
  std::string time_name;
  const FieldReader time = FindTimeField(message, &time_name, &to_seconds);
  std::vector<FieldReader> fields = {x, y, z};
  if (time.found) fields.push_back(time);
  if (!CheckLayout(message, fields, error)) return false;

  PointCloud2Scan decoded;
  decoded.stamp_s = message.stamp_s;
  decoded.frame_id = message.frame_id;
  decoded.time_field = time_name;
  decoded.cloud.Reserve(size_t{message.width} * message.height);
  for (uint32_t r = 0; r < message.height; ++r) {
    for (uint32_t c = 0; c < message.width; ++c) {
      const uint8_t* p = message.data + size_t{r} * message.row_step +
                         size_t{c} * message.point_step;
      const Eigen::Vector3d point(
          ReadValue(p, x), ReadValue(p, y), ReadValue(p, z));
      if (!point.allFinite()) continue;
      decoded.cloud.Add(point);
      if (!time.found) continue;
      double t = ReadValue(p, time) * to_seconds;
      if (time_name == "timestamp" && t > 1e6) t -= decoded.stamp_s;
      decoded.point_times_s.push_back(t);
    }
  }
  *scan = std::move(decoded);
  return true;
}

}  // namespace mlndt
