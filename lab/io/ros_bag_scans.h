#pragma once

// Point clouds from a ROS 1 bag: the sensor_msgs/PointCloud2 messages of one
// topic, in bag order, with their header stamps, the points' x/y/z and, when
// the message has one, the per-point time. Built with the ROS 1 libraries
// Debian packages (librosbag-storage-dev, libsensor-msgs-dev) when CMake
// finds them (MLNDT_WITH_ROSBAG); without them Open says so.
//
// Per-point time fields, by name: "time" (float32/64 s, Velodyne drivers),
// "t" (uint32 ns, Ouster), "offset_time" (uint32 ns, Livox), "timestamp"
// (float64 s, Hesai; absolute when larger than 1e6 s, then made relative to
// the header stamp). Non-finite points are dropped with their times, as the
// file readers drop them (mlndt/cloud/io.h).

#include <memory>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

// Whether this build reads ROS 1 bags.
bool RosBagSupported();

struct BagScan {
  double stamp_s = 0.0;  // header.stamp [s].
  std::string frame_id;
  PointCloud cloud;  // Sensor frame, finite points.
  // One per point of `cloud`, relative to stamp_s [s]; empty without a time
  // field.
  std::vector<double> point_times_s;
  std::string time_field;  // The field the times came from, or "".
};

class RosBagScans {
 public:
  // Opens `path` and indexes the messages on `topic`. False with *error
  // naming the file and, when the topic is missing or of another type, the
  // point-cloud topics the bag has.
  static bool Open(const std::string& path,
                   const std::string& topic,
                   std::unique_ptr<RosBagScans>* scans,
                   std::string* error);
  ~RosBagScans();

  size_t size() const;
  // Reads message i (0-based). False with *error on a malformed message
  // (no x/y/z float field, data shorter than its layout, ...).
  bool Read(size_t i, BagScan* scan, std::string* error) const;

  const std::string& path() const { return path_; }
  const std::string& topic() const { return topic_; }

 private:
  struct Impl;
  RosBagScans(std::string path, std::string topic, std::unique_ptr<Impl> impl);

  std::string path_;
  std::string topic_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mlndt
