#include "tools/cli/scan_input.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "lab/eval/dataset.h"
#include "lab/eval/scan_times.h"
#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/io.h"

// clang-format off
DEFINE_string(bag, "", "ROS 1 bag to read the scans from (sensor_msgs/PointCloud2 on --topic), "
              "instead of a folder");
DEFINE_string(topic, "", "With --bag: the PointCloud2 topic (default: the bag's one PointCloud2 "
              "topic)");
DEFINE_string(times, "", "Text file of scan time stamps [s], one line per scan (KITTI times.txt); "
              "without it and without --bag, TUM outputs use the scan index");
// clang-format on

namespace mlndt {
namespace tools {
namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

bool OpenBag(size_t max_scans,
             std::vector<std::string>* names,
             std::shared_ptr<RosBagScans>* bag,
             std::string* error) {
  if (!FLAGS_times.empty()) {
    *error =
        "--times does not apply to --bag (the bag's header stamps are "
        "the scans' times)";
    return false;
  }
  std::unique_ptr<RosBagScans> scans;
  if (!RosBagScans::Open(FLAGS_bag, FLAGS_topic, &scans, error)) {
    *error = "--bag=" + *error;
    return false;
  }
  size_t n = scans->size();
  if (max_scans > 0 && n > max_scans) n = max_scans;
  for (size_t i = 0; i < n; ++i) {
    names->push_back(scans->topic() + "#" + std::to_string(i));
  }
  *bag = std::move(scans);
  return true;
}

}  // namespace

bool ScanInputFromFlags(bool folder_given,
                        const std::function<bool(std::vector<std::string>*,
                                                 std::string*)>& list_folder,
                        size_t max_scans,
                        ScanInput* input,
                        std::string* error) {
  *input = ScanInput();
  if (!FLAGS_bag.empty()) {
    if (folder_given) {
      *error = "give either --bag or a folder of scans, not both";
      return false;
    }
    if (!OpenBag(max_scans, &input->names_, &input->bag_, error)) return false;
    input->stamps_s_.assign(input->names_.size(), kUnknown);
    input->topic_ = input->bag_->topic();
    input->time_source_ =
        "bag " + FLAGS_bag + " topic " + input->topic_ + ": header stamps";
    return true;
  }
  if (!FLAGS_topic.empty()) {
    *error = "--topic applies only with --bag";
    return false;
  }
  if (!list_folder(&input->paths_, error)) return false;
  const size_t listed = input->paths_.size();
  if (max_scans > 0 && listed > max_scans) input->paths_.resize(max_scans);
  for (const std::string& path : input->paths_) {
    input->names_.push_back(std::filesystem::path(path).filename().string());
  }
  input->stamps_s_.assign(input->paths_.size(), kUnknown);
  if (FLAGS_times.empty()) return true;
  std::vector<double> stamps;
  if (!ReadScanTimes(FLAGS_times, &stamps, error)) {
    *error = "--times=" + *error;
    return false;
  }
  if (stamps.size() != listed) {
    *error = "--times=" + FLAGS_times + " has " +
             std::to_string(stamps.size()) + " stamps for " +
             std::to_string(listed) + " scans (one per scan)";
    return false;
  }
  for (size_t i = 0; i < input->paths_.size(); ++i) {
    input->stamps_s_[i] = stamps[i];
  }
  input->time_source_ = "times file " + FLAGS_times;
  return true;
}

bool ScanInput::Load(size_t i,
                     PointCloud* cloud,
                     std::vector<double>* point_times_s,
                     std::string* error) {
  return LoadScan(i, false, cloud, point_times_s, error);
}

bool ScanInput::LoadScan(size_t i,
                         bool allow_empty,
                         PointCloud* cloud,
                         std::vector<double>* point_times_s,
                         std::string* error) {
  if (point_times_s != nullptr) point_times_s->clear();
  if (bag_ == nullptr) {
    if (!ReadPointCloud(paths_.at(i), cloud, nullptr, error)) return false;
    if (cloud->empty() && !allow_empty) {
      *error = paths_[i] + ": no finite points";
      return false;
    }
    return true;
  }
  BagScan scan;
  if (!bag_->Read(i, &scan, error)) return false;
  if (scan.cloud.empty() && !allow_empty) {
    *error = FLAGS_bag + ": " + names_.at(i) + ": no finite points";
    return false;
  }
  stamps_s_.at(i) = scan.stamp_s;
  *cloud = std::move(scan.cloud);
  if (point_times_s != nullptr) *point_times_s = std::move(scan.point_times_s);
  return true;
}

bool ScanInput::ReadBagStamps(std::string* error) {
  if (bag_ == nullptr) return true;
  for (size_t i = 0; i < names_.size(); ++i) {
    double stamp_s = 0.0;
    if (!bag_->ReadStamp(i, &stamp_s, error)) {
      *error = "--bag=" + *error;
      return false;
    }
    if (!std::isfinite(stamp_s) || (i > 0 && !(stamp_s > stamps_s_[i - 1]))) {
      char text[160];
      std::snprintf(text,
                    sizeof(text),
                    "header stamp %.9f s of message %zu is not after the "
                    "previous message's %.9f s",
                    stamp_s,
                    i,
                    i > 0 ? stamps_s_[i - 1] : stamp_s);
      *error = "--bag=" + FLAGS_bag + " --topic=" + topic_ + ": " + text +
               " (the scans need strictly increasing time stamps; a driver "
               "that does not stamp its messages gives 0)";
      return false;
    }
    stamps_s_[i] = stamp_s;
  }
  return true;
}

ScanLoader ScanInput::Loader(bool allow_empty) {
  return [this, allow_empty](size_t i, PointCloud* cloud, std::string* error) {
    return LoadScan(i, allow_empty, cloud, nullptr, error);
  };
}

OdometryScanLoader ScanInput::StampedLoader() {
  return [this](size_t i,
                PointCloud* cloud,
                std::vector<double>* point_times_s,
                double* stamp_s,
                std::string* error) {
    if (!Load(i, cloud, point_times_s, error)) return false;
    *stamp_s = StampOf(i);
    return true;
  };
}

double ScanInput::StampOf(size_t i) const {
  const double stamp = stamps_s_.at(i);
  return std::isnan(stamp) ? static_cast<double>(i) : stamp;
}

std::string ScanInput::TumComment() const {
  if (has_stamps()) return "time stamps: " + time_source_;
  return std::string(kTumIndexStampsComment) +
         ": give --times or --bag for real stamps";
}

bool ScanInputFromScansFlag(const std::string& scans_dir,
                            const std::vector<std::string>& other_inputs,
                            size_t max_scans,
                            ScanInput* input,
                            std::string* error) {
  const auto list_folder = [&](std::vector<std::string>* paths,
                               std::string* list_error) {
    return ListScanFiles(scans_dir, other_inputs, paths, list_error);
  };
  return ScanInputFromFlags(
      !scans_dir.empty(), list_folder, max_scans, input, error);
}

}  // namespace tools
}  // namespace mlndt
