// RosBagScans with the ROS 1 libraries (rosbag_storage, sensor_msgs).
#include "lab/io/ros_bag_scans.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud2.h>

#include <set>

namespace mlndt {
namespace {

// The first fields of a message that starts with a std_msgs/Header, as
// sensor_msgs/PointCloud2 does: read without the rest of the message.
struct HeaderStamp {
  uint32_t seq = 0;
  ros::Time stamp;
};

}  // namespace
}  // namespace mlndt

namespace ros {
namespace message_traits {
// "*" matches every message type, as topic_tools::ShapeShifter's does;
// Open checked that the topic's type is PointCloud2.
template <>
struct MD5Sum<mlndt::HeaderStamp> {
  static const char* value() { return "*"; }
  static const char* value(const mlndt::HeaderStamp&) { return value(); }
};
}  // namespace message_traits
namespace serialization {
template <>
struct Serializer<mlndt::HeaderStamp> {
  template <typename Stream>
  static void read(Stream& stream, mlndt::HeaderStamp& header) {
    stream.next(header.seq);
    stream.next(header.stamp);
  }
};
}  // namespace serialization
}  // namespace ros

namespace mlndt {
namespace {

constexpr char kPointCloud2[] = "sensor_msgs/PointCloud2";

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

// The bag's one PointCloud2 topic into *topic; false with *error naming the
// topics when it has none or several.
bool OnlyPointCloudTopic(const rosbag::Bag& bag,
                         std::string* topic,
                         std::string* error) {
  rosbag::View all(bag);
  std::set<std::string> clouds;
  for (const rosbag::ConnectionInfo* info : all.getConnections()) {
    if (info->datatype == kPointCloud2) clouds.insert(info->topic);
  }
  if (clouds.size() == 1) {
    *topic = *clouds.begin();
    return true;
  }
  *error = (clouds.empty() ? std::string("no ")
                           : std::to_string(clouds.size()) + " ") +
           kPointCloud2 + " topics, give one with --topic; the bag has " +
           DescribeTopics(bag);
  return false;
}

}  // namespace

struct RosBagScans::Impl {
  rosbag::Bag bag;
  std::unique_ptr<rosbag::View> view;
  std::vector<rosbag::MessageInstance> messages;
};

bool RosBagSupported() { return true; }

bool RosBagScans::Open(const std::string& path,
                       const std::string& given_topic,
                       std::unique_ptr<RosBagScans>* scans,
                       std::string* error) {
  auto impl = std::make_unique<Impl>();
  std::string topic = given_topic;
  try {
    impl->bag.open(path, rosbag::bagmode::Read);
    if (topic.empty() && !OnlyPointCloudTopic(impl->bag, &topic, error)) {
      *error = path + ": " + *error;
      return false;
    }
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

namespace {

// Runs `read(message, error)` on message `i`, with its bounds checked, its
// exceptions caught and every error prefixed with where it happened.
template <typename Read>
bool ReadMessage(const std::string& path,
                 const std::string& topic,
                 const std::vector<rosbag::MessageInstance>& messages,
                 size_t i,
                 std::string* error,
                 Read read) {
  const std::string where =
      path + ": " + topic + " message " + std::to_string(i);
  if (i >= messages.size()) {
    *error = where + ": the topic has " + std::to_string(messages.size()) +
             " messages";
    return false;
  }
  try {
    if (read(messages[i], error)) return true;
  } catch (const std::exception& e) {
    *error = e.what();
  }
  *error = where + ": " + *error;
  return false;
}

}  // namespace

bool RosBagScans::Read(size_t i, BagScan* scan, std::string* error) const {
  return ReadMessage(
      path_,
      topic_,
      impl_->messages,
      i,
      error,
      [scan](const rosbag::MessageInstance& instance, std::string* error) {
        const sensor_msgs::PointCloud2::ConstPtr message =
            instance.instantiate<sensor_msgs::PointCloud2>();
        if (message == nullptr) {
          *error = std::string("not a ") + kPointCloud2;
          return false;
        }
        return DecodePointCloud2(
            PointCloud2ViewOf(*message, message->header.stamp.toSec()),
            scan,
            error);
      });
}

bool RosBagScans::ReadStamp(size_t i,
                            double* stamp_s,
                            std::string* error) const {
  return ReadMessage(
      path_,
      topic_,
      impl_->messages,
      i,
      error,
      [stamp_s](const rosbag::MessageInstance& instance, std::string* error) {
        const boost::shared_ptr<HeaderStamp> header =
            instance.instantiate<HeaderStamp>();
        if (header == nullptr) {
          *error = "no header";
          return false;
        }
        *stamp_s = header->stamp.toSec();
        return true;
      });
}

}  // namespace mlndt
