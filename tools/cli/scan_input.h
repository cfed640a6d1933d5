#pragma once

// Where a tool's scans come from, shared by mlndt_sequence, mlndt_odometry,
// mlndt_map and mlndt_localize: a folder (or list) of point-cloud files, or
// a ROS 1 bag's PointCloud2 topic (--bag=FILE [--topic=NAME]), and the scans'
// time stamps: the bag's header stamps, a --times file (one stamp per scan)
// or, when neither is given, the scan indices (TUM outputs then say so in
// their header).

#include <gflags/gflags.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lab/io/ros_bag_scans.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/odometry/run_odometry.h"
#include "mlndt/pipeline/localizer.h"

DECLARE_string(bag);
DECLARE_string(topic);
DECLARE_string(times);

namespace mlndt {
namespace tools {

class ScanInput {
 public:
  size_t size() const { return names_.size(); }
  bool from_bag() const { return bag_ != nullptr; }
  // The bag's topic read (--topic, or the bag's one PointCloud2 topic);
  // empty for a folder.
  const std::string& topic() const { return topic_; }
  // The file paths (folder input; empty for a bag).
  const std::vector<std::string>& paths() const { return paths_; }
  // File name, or "<topic>#<i>" for a bag.
  const std::string& name(size_t i) const { return names_.at(i); }
  const std::vector<std::string>& names() const { return names_; }

  // Scan i in its sensor frame and, when the bag has a time field, its
  // per-point times (else *point_times_s is cleared; may be null). Records
  // the bag stamp of the scan.
  bool Load(size_t i,
            PointCloud* cloud,
            std::vector<double>* point_times_s,
            std::string* error);
  // Load without point times, for ScanStore and LocalizeScans. With
  // `allow_empty` a scan without a finite point loads as an empty cloud
  // (mlndt_map reports it and goes on) instead of being an error.
  ScanLoader Loader(bool allow_empty = false);
  // Load with the point times and StampOf the scan, for RunOdometry.
  OdometryScanLoader StampedLoader();

  // For a bag: reads the header stamps of the scans now and checks that
  // they are finite and increase strictly, as ReadScanTimes checks a
  // --times file (a driver that does not stamp gives 0s). For the tools
  // whose outputs are stamped (TUM trajectories, the odometry's
  // prediction). True for a folder. False with *error naming the bag, the
  // message and its stamp: the tool refuses the input before any work.
  bool ReadBagStamps(std::string* error);

  // Whether scans have real time stamps (a bag or --times).
  bool has_stamps() const { return !time_source_.empty(); }
  // The stamp of scan i [s]: from --times, from the bag once the scan was
  // loaded, else i.
  double StampOf(size_t i) const;
  // The header line of TUM outputs: where the stamps come from.
  std::string TumComment() const;

 private:
  bool LoadScan(size_t i,
                bool allow_empty,
                PointCloud* cloud,
                std::vector<double>* point_times_s,
                std::string* error);
  friend bool ScanInputFromFlags(
      bool,
      const std::function<bool(std::vector<std::string>*, std::string*)>&,
      size_t,
      ScanInput*,
      std::string*);

  std::vector<std::string> paths_;
  std::vector<std::string> names_;
  std::vector<double> stamps_s_;  // NaN until known.
  std::string time_source_;
  std::shared_ptr<RosBagScans> bag_;
  std::string topic_;
};

// The scans from the flags: --bag with --topic, or the tool's own folder
// flags (`folder_given`; `list_folder` lists their files), exactly one of
// them; the first `max_scans` when > 0; --times=FILE stamps them (not with
// --bag, which has its stamps; exactly one stamp per scan before
// max_scans). False with *error naming the flag or file: the tool's usage
// error (exit 2, before any work).
bool ScanInputFromFlags(bool folder_given,
                        const std::function<bool(std::vector<std::string>*,
                                                 std::string*)>& list_folder,
                        size_t max_scans,
                        ScanInput* input,
                        std::string* error);

// ScanInputFromFlags for a tool whose folder flag is --scans=`scans_dir`:
// its point-cloud files (ListScanFiles) but `other_inputs` (pose, calib and
// times files that may lie in the same folder).
bool ScanInputFromScansFlag(const std::string& scans_dir,
                            const std::vector<std::string>& other_inputs,
                            size_t max_scans,
                            ScanInput* input,
                            std::string* error);

}  // namespace tools
}  // namespace mlndt
