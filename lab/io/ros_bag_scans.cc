// RosBagScans with the ROS 1 libraries (rosbag_storage, sensor_msgs).
#include "lab/io/ros_bag_scans.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud2.h>

#include <cmath>
#include <cstring>
#include <set>

namespace mlndt {
namespace {

constexpr char kPointCloud2[] = "sensor_msgs/PointCloud2";

// Where a field is and how to read it.
struct FieldReader {
  bool found = false;
  uint32_t offset = 0;
  uint8_t datatype = 0;
};

FieldReader FindField(const sensor_msgs::PointCloud2& message,
                      const std::string& name) {
  FieldReader reader;
  for (const sensor_msgs::PointField& field : message.fields) {
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
    case sensor_msgs::PointField::INT8:
    case sensor_msgs::PointField::UINT8:
      return 1;
    case sensor_msgs::PointField::INT16:
    case sensor_msgs::PointField::UINT16:
      return 2;
    case sensor_msgs::PointField::INT32:
    case sensor_msgs::PointField::UINT32:
    case sensor_msgs::PointField::FLOAT32:
      return 4;
    case sensor_msgs::PointField::FLOAT64:
      return 8;
  }
  return 0;
}

// The value of a field of the point at `data` as a double (little-endian
// host; big-endian messages are refused before).
double ReadValue(const uint8_t* data, const FieldReader& field) {
  const uint8_t* p = data + field.offset;
  switch (field.datatype) {
    case sensor_msgs::PointField::FLOAT32: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case sensor_msgs::PointField::FLOAT64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
    case sensor_msgs::PointField::UINT32: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case sensor_msgs::PointField::INT32: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
  return NAN;
}

// The per-point time field and the factor to seconds, if the message has
// one of the known ones.
FieldReader FindTimeField(const sensor_msgs::PointCloud2& message,
                          std::string* name,
                          double* to_seconds) {
  for (const char* candidate : {"time", "t", "offset_time", "timestamp"}) {
    FieldReader field = FindField(message, candidate);
    if (!field.found) continue;
    const bool is_float = field.datatype == sensor_msgs::PointField::FLOAT32 ||
                          field.datatype == sensor_msgs::PointField::FLOAT64;
    const bool is_int = field.datatype == sensor_msgs::PointField::UINT32 ||
                        field.datatype == sensor_msgs::PointField::INT32;
    if (!is_float && !is_int) continue;
    *name = candidate;
    *to_seconds = is_float ? 1.0 : 1e-9;
    return field;
  }
  return FieldReader();
}

bool CheckLayout(const sensor_msgs::PointCloud2& message,
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
  if (message.row_step < row ||
      uint64_t{message.row_step} * message.height > message.data.size()) {
    *error = "data holds " + std::to_string(message.data.size()) +
             " bytes, fewer than height x row_step (" +
             std::to_string(message.height) + " x " +
             std::to_string(message.row_step) + ")";
    return false;
  }
  return true;
}

// Decodes x/y/z and the per-point time of `message` into *scan.
bool Decode(const sensor_msgs::PointCloud2& message,
            BagScan* scan,
            std::string* error) {
  const FieldReader x = FindField(message, "x"), y = FindField(message, "y"),
                    z = FindField(message, "z");
  for (const FieldReader* f : {&x, &y, &z}) {
    if (!f->found || (f->datatype != sensor_msgs::PointField::FLOAT32 &&
                      f->datatype != sensor_msgs::PointField::FLOAT64)) {
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

  scan->stamp_s = message.header.stamp.toSec();
  scan->frame_id = message.header.frame_id;
  scan->time_field = time_name;
  scan->cloud = PointCloud();
  scan->point_times_s.clear();
  scan->cloud.Reserve(size_t{message.width} * message.height);
  for (uint32_t r = 0; r < message.height; ++r) {
    for (uint32_t c = 0; c < message.width; ++c) {
      const uint8_t* p = message.data.data() + size_t{r} * message.row_step +
                         size_t{c} * message.point_step;
      const Eigen::Vector3d point(
          ReadValue(p, x), ReadValue(p, y), ReadValue(p, z));
      if (!point.allFinite()) continue;
      scan->cloud.Add(point);
      if (!time.found) continue;
      double t = ReadValue(p, time) * to_seconds;
      if (time_name == "timestamp" && t > 1e6) t -= scan->stamp_s;
      scan->point_times_s.push_back(t);
    }
  }
  return true;
}

// "topic (type)" of every connection, for messages.
std::string DescribeTopics(const rosbag::Bag& bag) {
  rosbag::View all(bag);
  std::set<std::string> topics;
  for (const rosbag::ConnectionInfo* info : all.getConnections()) {
    topics.insert(info->topic + " (" + info->datatype + ")");
  }
  std::string text;
  for (const std::string& t : topics) text += (text.empty() ? "" : ", ") + t;
  return text.empty() ? "none" : text;
}

}  // namespace

struct RosBagScans::Impl {
  rosbag::Bag bag;
  std::unique_ptr<rosbag::View> view;
  std::vector<rosbag::MessageInstance> messages;
};

bool RosBagSupported() { return true; }

bool RosBagScans::Open(const std::string& path,
                       const std::string& topic,
                       std::unique_ptr<RosBagScans>* scans,
                       std::string* error) {
  auto impl = std::make_unique<Impl>();
  try {
    impl->bag.open(path, rosbag::bagmode::Read);
    impl->view =
        std::make_unique<rosbag::View>(impl->bag, rosbag::TopicQuery(topic));
    for (const rosbag::ConnectionInfo* info : impl->view->getConnections()) {
      if (info->datatype != kPointCloud2) {
        *error = path + ": topic " + topic + " is " + info->datatype +
                 ", not " + kPointCloud2 + "; the bag has " +
                 DescribeTopics(impl->bag);
        return false;
      }
    }
    for (const rosbag::MessageInstance& m : *impl->view) {
      impl->messages.push_back(m);
    }
  } catch (const std::exception& e) {
    *error = path + ": " + e.what();
    return false;
  }
  if (impl->messages.empty()) {
    *error = path + ": no messages on topic '" + topic + "'; the bag has " +
             DescribeTopics(impl->bag);
    return false;
  }
  scans->reset(new RosBagScans(path, topic, std::move(impl)));
  return true;
}

RosBagScans::RosBagScans(std::string path,
                         std::string topic,
                         std::unique_ptr<Impl> impl)
    : path_(std::move(path)),
      topic_(std::move(topic)),
      impl_(std::move(impl)) {}

RosBagScans::~RosBagScans() = default;

size_t RosBagScans::size() const { return impl_->messages.size(); }

bool RosBagScans::Read(size_t i, BagScan* scan, std::string* error) const {
  const std::string where =
      path_ + ": " + topic_ + " message " + std::to_string(i);
  if (i >= impl_->messages.size()) {
    *error = where + ": the topic has " +
             std::to_string(impl_->messages.size()) + " messages";
    return false;
  }
  try {
    const sensor_msgs::PointCloud2::ConstPtr message =
        impl_->messages[i].instantiate<sensor_msgs::PointCloud2>();
    if (message == nullptr) {
      *error = where + ": not a " + kPointCloud2;
      return false;
    }
    if (!Decode(*message, scan, error)) {
      *error = where + ": " + *error;
      return false;
    }
  } catch (const std::exception& e) {
    *error = where + ": " + e.what();
    return false;
  }
  return true;
}

}  // namespace mlndt
