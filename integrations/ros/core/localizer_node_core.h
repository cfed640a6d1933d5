#pragma once

// The map-localisation node without the middleware: holds the map (a file
// of mlndt_map), takes the first pose (a parameter, or RViz's "2D Pose
// Estimate" on /initialpose), localises each cloud as mlndt_localize does
// (Localizer, mlndt/pipeline/localizer.h: the same prediction, the same
// registration, so the same poses on the same clouds) and says what to
// publish: the pose with its covariance and map -> odom (map -> sensor
// without an odometry, ~odom_frame empty).
//
// A result that is not to be used (LOW_QUALITY, DEGENERATE, FAILURE) makes
// no jump: no pose is published, map -> odom stays where the last usable
// one put it (re-stamped), and a warning and a WARN/ERROR diagnostic say
// so; the Localizer starts the next scan from the last usable pose, with an
// uncertainty grown by the gap, as the tool does. Clouds before the first pose
// wait (waiting_for_initial_pose); a malformed or empty cloud or a stamp not
// after the last one is refused as the odometry node refuses it.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "integrations/ros/core/diagnostic_report.h"
#include "integrations/ros/core/localizer_parameters.h"
#include "integrations/ros/core/scan_report.h"
#include "integrations/ros/core/stamp_check.h"
#include "lab/io/point_cloud2.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/pipeline/localizer.h"

namespace mlndt {
namespace ros_core {

// The odometry's pose at a cloud's stamp (odom -> sensor on tf).
struct OdomPose {
  bool available = false;
  Isometry3d odom_from_sensor = Isometry3d::Identity();
};

struct LocalizerNodeOutput {
  double stamp_s = 0.0;
  std::string frame_id;  // The cloud's header.frame_id.
  bool waiting_for_initial_pose = false;
  // The cloud was localised (report holds the result).
  bool processed = false;
  // The result is usable: publish report.pose (map_from_sensor) with
  // `covariance`.
  bool has_pose = false;
  ScanReport report;
  std::array<double, 36> covariance{};  // ros_pose.h's order.
  // The transform to publish at stamp_s: map_from_odom, or map_from_sensor
  // without an odometry.
  bool has_transform = false;
  Isometry3d map_from_child = Isometry3d::Identity();
  // An unusable result left the transform where it was.
  bool jump_refused = false;
  DiagnosticReport diagnostic;  // Not for waiting_for_initial_pose.
  std::vector<std::string> warnings;
};

class LocalizerNodeCore {
 public:
  // Loads options.map_path (LoadLayeredGrid) and checks a given
  // ~start_layer against its layers; false with *error.
  static bool Create(const LocalizerNodeOptions& options,
                     std::unique_ptr<LocalizerNodeCore>* core,
                     std::string* error);

  // (Re)starts the localisation from `map_from_sensor` at the next cloud.
  void SetInitialPose(const Isometry3d& map_from_sensor);
  bool has_initial_pose() const { return localizer_ != nullptr; }

  LocalizerNodeOutput ProcessMessage(const PointCloud2View& message,
                                     const OdomPose& odom);
  LocalizerNodeOutput Process(const PointCloud2Scan& scan,
                              const OdomPose& odom);

  const LocalizerNodeOptions& options() const { return options_; }
  const LayeredGrid& map() const { return map_; }
  // Whether map -> odom is published (else map -> sensor).
  bool with_odometry() const { return !options_.odom_frame.empty(); }

 private:
  explicit LocalizerNodeCore(const LocalizerNodeOptions& options)
      : options_(options) {}
  LocalizerNodeOutput Refuse(double stamp_s,
                             const std::string& frame_id,
                             const std::string& reason) const;
  void SetTransform(const OdomPose& odom, LocalizerNodeOutput* output);

  LocalizerNodeOptions options_;
  LayeredGrid map_;
  // Refers to map_; null until an initial pose is set.
  std::unique_ptr<Localizer> localizer_;
  StampCheck stamps_;
  bool has_map_from_child_ = false;
  Isometry3d map_from_child_ = Isometry3d::Identity();
};

}  // namespace ros_core
}  // namespace mlndt
