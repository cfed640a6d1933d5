#pragma once

// sensor_msgs/PointCloud2 -> points and per-point times, without the
// middleware: the one decoder behind the ROS 1 bag reader
// (ros_bag_scans.h) and the ROS nodes (integrations/ros/), so a node fed a
// bag's messages gets the points and times the tools read from the bag.
// ROS 1's sensor_msgs::PointCloud2 and ROS 2's sensor_msgs::msg::PointCloud2
// have the same fields; PointCloud2ViewOf reads either.
//
// Per-point time fields, by name, the first found: "time" (float32/64 s,
// Velodyne drivers), "t" (uint32 ns, Ouster), "offset_time" (uint32 ns,
// Livox), "timestamp" (float64 s, Hesai; absolute when larger than 1e6 s,
// then made relative to the header stamp). Non-finite points are dropped
// with their times, as the file readers drop them (mlndt/cloud/io.h).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

// sensor_msgs/PointField's datatype constants (the same in ROS 1 and 2).
enum PointCloud2Datatype : uint8_t {
  kPointFieldInt8 = 1,
  kPointFieldUint8 = 2,
  kPointFieldInt16 = 3,
  kPointFieldUint16 = 4,
  kPointFieldInt32 = 5,
  kPointFieldUint32 = 6,
  kPointFieldFloat32 = 7,
  kPointFieldFloat64 = 8,
};

struct PointCloud2Field {
  std::string name;
  uint32_t offset = 0;  // Bytes from the start of a point.
  uint8_t datatype = 0;
};

// A message's layout and data, borrowed (`data` must outlive the view).
struct PointCloud2View {
  double stamp_s = 0.0;  // header.stamp [s].
  std::string frame_id;
  uint32_t height = 0;
  uint32_t width = 0;
  std::vector<PointCloud2Field> fields;
  bool is_bigendian = false;
  uint32_t point_step = 0;  // Bytes per point.
  uint32_t row_step = 0;    // Bytes per row.
  const uint8_t* data = nullptr;
  size_t data_size = 0;
};

// One decoded message.
struct PointCloud2Scan {
  double stamp_s = 0.0;  // header.stamp [s].
  std::string frame_id;
  PointCloud cloud;  // Sensor frame, finite points.
  // One per point of `cloud`, relative to stamp_s [s]; empty without a time
  // field.
  std::vector<double> point_times_s;
  std::string time_field;  // The field the times came from, or "".
};

// The view of a ROS 1 or ROS 2 PointCloud2 message; `stamp_s` is its
// header stamp in seconds (the two middlewares' stamp types differ).
template <typename Message>
PointCloud2View PointCloud2ViewOf(const Message& message, double stamp_s) {
  PointCloud2View view;
  view.stamp_s = stamp_s;
  view.frame_id = message.header.frame_id;
  view.height = message.height;
  view.width = message.width;
  for (const auto& field : message.fields) {
    view.fields.push_back({field.name, field.offset, field.datatype});
  }
  view.is_bigendian = message.is_bigendian;
  view.point_step = message.point_step;
  view.row_step = message.row_step;
  view.data = message.data.data();
  view.data_size = message.data.size();
  return view;
}

// Decodes x/y/z (float32 or float64) and the per-point time of `message`
// into *scan. False with *error, *scan unchanged, on a layout it cannot
// read: no float x, y and z fields, big-endian data, a field outside
// point_step, data shorter than height x row_step. A message without a
// finite point decodes to an empty cloud (callers decide what that means).
bool DecodePointCloud2(const PointCloud2View& message,
                       PointCloud2Scan* scan,
                       std::string* error);

}  // namespace mlndt
