#include "integrations/ros/core/localizer_node_core.h"

#include <cstdio>

#include "integrations/ros/core/ros_pose.h"
#include "mlndt/grid/grid_io.h"

namespace mlndt {
namespace ros_core {
namespace {

std::string At(double stamp_s) {
  char text[64];
  std::snprintf(text, sizeof(text), "scan at %.6f s: ", stamp_s);
  return text;
}

// The rule of mlndt_localize's --start_layer check: 1..n, or 1-n..0 from
// the finest.
bool CheckStartLayer(int start_layer, int num_layers, std::string* error) {
  const int resolved = start_layer > 0 ? start_layer : num_layers + start_layer;
  if (resolved >= 1 && resolved <= num_layers) return true;
  *error = "~start_layer=" + std::to_string(start_layer) +
           " is out of range: the map has " + std::to_string(num_layers) +
           " layer(s); give 1.." + std::to_string(num_layers) + " or " +
           std::to_string(1 - num_layers) + "..0 (from the finest)";
  return false;
}

}  // namespace

bool LocalizerNodeCore::Create(const LocalizerNodeOptions& options,
                               std::unique_ptr<LocalizerNodeCore>* core,
                               std::string* error) {
  std::unique_ptr<LocalizerNodeCore> created(new LocalizerNodeCore(options));
  if (!LoadLayeredGrid(options.map_path, &created->map_, error)) return false;
  if (options.start_layer_given &&
      !CheckStartLayer(options.localizer.registration.schedule.start_layer,
                       created->map_.num_layers(),
                       error)) {
    return false;
  }
  if (options.has_initial_pose) {
    created->SetInitialPose(options.initial_map_from_sensor);
  }
  *core = std::move(created);
  return true;
}

void LocalizerNodeCore::SetInitialPose(const Isometry3d& map_from_sensor) {
  localizer_ =
      std::make_unique<Localizer>(options_.localizer, map_, map_from_sensor);
  stamps_.Reset();
}

LocalizerNodeOutput LocalizerNodeCore::ProcessMessage(
    const PointCloud2View& message, const OdomPose& odom) {
  PointCloud2Scan scan;
  std::string error;
  if (!DecodePointCloud2(message, &scan, &error)) {
    return Refuse(message.stamp_s, message.frame_id, "malformed: " + error);
  }
  return Process(scan, odom);
}

LocalizerNodeOutput LocalizerNodeCore::Refuse(double stamp_s,
                                              const std::string& frame_id,
                                              const std::string& reason) const {
  LocalizerNodeOutput output;
  output.stamp_s = stamp_s;
  output.frame_id = frame_id;
  output.diagnostic = RefusedDiagnostic(stamp_s, reason);
  output.warnings.push_back(At(stamp_s) + "not used: " + reason);
  return output;
}

LocalizerNodeOutput LocalizerNodeCore::Process(const PointCloud2Scan& scan,
                                               const OdomPose& odom) {
  if (localizer_ == nullptr) {
    LocalizerNodeOutput output;
    output.stamp_s = scan.stamp_s;
    output.frame_id = scan.frame_id;
    output.waiting_for_initial_pose = true;
    return output;
  }
  if (scan.cloud.empty()) {
    return Refuse(scan.stamp_s, scan.frame_id, "no finite points");
  }
  std::string refusal, gap;
  if (!stamps_.Check(scan.stamp_s, &refusal, &gap)) {
    return Refuse(scan.stamp_s, scan.frame_id, refusal);
  }
  stamps_.Use(scan.stamp_s);
  LocalizationResult result;
  localizer_->Localize(scan.cloud, &result);

  LocalizerNodeOutput output;
  output.stamp_s = scan.stamp_s;
  output.frame_id = scan.frame_id;
  output.processed = true;
  output.report = ReportOf(result, scan.stamp_s);
  output.has_pose = output.report.registered;
  output.covariance = ToRosCovariance(output.report.pose,
                                      output.report.covariance,
                                      output.report.has_covariance);
  output.diagnostic = ScanDiagnostic(output.report, false);
  if (!gap.empty()) output.warnings.push_back(At(scan.stamp_s) + gap);
  SetTransform(odom, &output);
  return output;
}

void LocalizerNodeCore::SetTransform(const OdomPose& odom,
                                     LocalizerNodeOutput* output) {
  const std::string child = with_odometry() ? "map -> odom" : "map -> sensor";
  if (!output->has_pose) {
    output->jump_refused = true;
    output->warnings.push_back(
        At(output->stamp_s) + output->diagnostic.message +
        "; no jump: " + child + (with_odometry() ? " kept" : " not updated"));
    // Without an odometry the sensor moves on: the last map -> sensor does
    // not hold it, so nothing is published.
    output->has_transform = with_odometry() && has_map_from_child_;
    output->map_from_child = map_from_child_;
    output->diagnostic.values.push_back({"jump_refused", "true"});
    return;
  }
  if (with_odometry() && !odom.available) {
    output->warnings.push_back(
        At(output->stamp_s) +
        "no odom -> sensor on tf at this stamp: " + child + " not updated");
    output->has_transform = has_map_from_child_;
    output->map_from_child = map_from_child_;
    return;
  }
  map_from_child_ = with_odometry()
                        ? output->report.pose * odom.odom_from_sensor.inverse()
                        : output->report.pose;
  has_map_from_child_ = true;
  output->has_transform = true;
  output->map_from_child = map_from_child_;
}

}  // namespace ros_core
}  // namespace mlndt
