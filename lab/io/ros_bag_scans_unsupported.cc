// RosBagScans for a build without the ROS 1 libraries (MLNDT_WITH_ROSBAG
// off): every Open says so.
#include "lab/io/ros_bag_scans.h"

namespace mlndt {

struct RosBagScans::Impl {};

bool RosBagSupported() { return false; }

bool RosBagScans::Open(const std::string& path,
                       const std::string&,
                       std::unique_ptr<RosBagScans>*,
                       std::string* error) {
  *error = path +
           ": this build reads no ROS bags (configure with "
           "-DMLNDT_WITH_ROSBAG=ON after scripts/install_deps.sh installs "
           "librosbag-storage-dev and libsensor-msgs-dev)";
  return false;
}

RosBagScans::RosBagScans(std::string path,
                         std::string topic,
                         std::unique_ptr<Impl> impl)
    : path_(std::move(path)),
      topic_(std::move(topic)),
      impl_(std::move(impl)) {}

RosBagScans::~RosBagScans() = default;

size_t RosBagScans::size() const { return 0; }

bool RosBagScans::Read(size_t, BagScan*, std::string* error) const {
  *error = path_ + ": this build reads no ROS bags";
  return false;
}

bool RosBagScans::ReadStamp(size_t, double*, std::string* error) const {
  *error = path_ + ": this build reads no ROS bags";
  return false;
}

}  // namespace mlndt
