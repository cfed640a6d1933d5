#pragma once

// Point clouds from a ROS 1 bag: the sensor_msgs/PointCloud2 messages of one
// topic, in bag order, with their header stamps, the points' x/y/z and, when
// the message has one, the per-point time. Built with the ROS 1 libraries
// Debian packages (librosbag-storage-dev, libsensor-msgs-dev) when CMake
// finds them (MLNDT_WITH_ROSBAG); without them Open says so.
//
// The messages are decoded by DecodePointCloud2 (point_cloud2.h, which
// names the per-point time fields it reads), the decoder the ROS nodes use.

#include <memory>
#include <string>
#include <vector>

#include "lab/io/point_cloud2.h"

namespace mlndt {

// Whether this build reads ROS 1 bags.
bool RosBagSupported();

// One message of the topic (point_cloud2.h).
using BagScan = PointCloud2Scan;

class RosBagScans {
 public:
  // Opens `path` and indexes the messages on `topic`; an empty `topic` is
  // the bag's one sensor_msgs/PointCloud2 topic (an error naming them when
  // it has none or several). False with *error naming the file and, when
  // the topic is missing or of another type, the topics the bag has.
  static bool Open(const std::string& path,
                   const std::string& topic,
                   std::unique_ptr<RosBagScans>* scans,
                   std::string* error);
  ~RosBagScans();

  size_t size() const;
  // Reads message i (0-based). False with *error on a malformed message
  // (no x/y/z float field, data shorter than its layout, ...).
  bool Read(size_t i, BagScan* scan, std::string* error) const;
  // The header stamp of message i [s], read without decoding the points.
  // False with *error as Read.
  bool ReadStamp(size_t i, double* stamp_s, std::string* error) const;

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
