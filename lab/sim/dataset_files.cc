#include "lab/sim/dataset_files.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "lab/sim/scan_pcd.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Json Matrix3x4(const Isometry3d& transform) {
  Json numbers = Json::array();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) numbers.push_back(transform.matrix()(r, c));
  }
  return numbers;
}

// Rounded to 1e-12 (no -0), for directions and other derived vectors.
Json Rounded(const Eigen::VectorXd& v) {
  Json numbers = Json::array();
  for (int k = 0; k < v.size(); ++k) {
    const double r = std::round(v(k) * 1e12) / 1e12;
    numbers.push_back(r == 0.0 ? 0.0 : r);
  }
  return numbers;
}

Json FreeDirections(const PairConstraints& constraints) {
  Json directions = Json::array();
  for (const Vector6d& d : constraints.free_directions) {
    directions.push_back(Rounded(d));
  }
  return directions;
}

std::string PairKey(const SimPair& pair) {
  return std::to_string(pair.reference) + "_" + std::to_string(pair.input);
}

std::string ScanFile(size_t k) {
  char name[32];
  std::snprintf(name, sizeof(name), "pcd/%06zu.pcd", k);
  return name;
}

Json SensorJson(const SensorModel& sensor) {
  const ReturnOptions& r = sensor.returns;
  Json json = {{"name", sensor.name},
               {"min_range_m", r.min_range_m},
               {"max_range_m", r.max_range_m},
               {"range_sigma_m", r.range_sigma_m},
               {"dropout_probability", r.dropout_probability},
               {"min_cos_incidence", r.min_cos_incidence},
               {"keep_every", r.keep_every}};
  if (sensor.pattern == ScanPattern::SPINNING) {
    json["pattern"] = "spinning";
    json["vertical_angles_deg"] = sensor.spinning.vertical_angles_deg;
    json["azimuth_resolution_deg"] = sensor.spinning.azimuth_resolution_deg;
    json["sweep_period_s"] = sensor.spinning.sweep_period_s;
  } else if (sensor.pattern == ScanPattern::ROSETTE) {
    const RosetteSensorOptions& o = sensor.rosette;
    json["pattern"] = "rosette";
    json["fov_deg"] = {o.horizontal_fov_deg, o.vertical_fov_deg};
    json["lasers"] = o.num_lasers;
    json["points_per_second"] = o.points_per_second;
    json["frame_period_s"] = o.frame_period_s;
    json["prism_frequencies_hz"] = {o.prism_frequency_1_hz,
                                    o.prism_frequency_2_hz};
  } else {
    const RasterSensorOptions& o = sensor.raster;
    json["pattern"] = "raster";
    json["fov_deg"] = {o.horizontal_fov_deg, o.vertical_fov_deg};
    json["resolution_deg"] = {o.horizontal_resolution_deg,
                              o.vertical_resolution_deg};
    json["frame_period_s"] = o.frame_period_s;
  }
  return json;
}

Json TrajectoryJson(const SimulationOptions& options) {
  if (options.TrajectoryKind() == "car") {
    const CarTrajectoryOptions& c = options.car;
    return {{"kind", "car"},
            {"step_m", {c.min_step_m, c.max_step_m}},
            {"yaw_step_deg", c.yaw_step_deg},
            {"max_yaw_offset_deg", c.max_yaw_offset_deg},
            {"max_tilt_deg", c.max_tilt_deg},
            {"height_m", {c.min_height_m, c.max_height_m}},
            {"scan_interval_s", c.scan_interval_s}};
  }
  const HandheldTrajectoryOptions& h = options.handheld;
  return {{"kind", "handheld"},
          {"step_m", {h.min_step_m, h.max_step_m}},
          {"rotation_deg", {h.min_rotation_deg, h.max_rotation_deg}},
          {"shake", h.shake},
          {"max_tilt_deg", h.max_tilt_deg},
          {"max_heading_offset_deg", h.max_heading_offset_deg},
          {"lookahead_m", h.lookahead_m},
          {"height_m", {h.min_height_m, h.max_height_m}},
          {"scan_interval_s", h.scan_interval_s}};
}

Json ScansJson(const SimDataset& dataset) {
  Json scans = Json::array();
  for (size_t k = 0; k < dataset.scans.size(); ++k) {
    scans.push_back({{"index", k},
                     {"file", ScanFile(k)},
                     {"stamp_s", dataset.trajectory.stamps_s[k]},
                     {"rays", dataset.scans[k].rays},
                     {"points", dataset.scans[k].points.size()},
                     {"velocity", Rounded(dataset.trajectory.Velocity(k))}});
  }
  return scans;
}

Json PairsJson(const SimDataset& dataset) {
  Json pairs = Json::object();
  for (const SimPair& pair : dataset.pairs) {
    const PairConstraints& c = pair.constraints;
    const Eigen::AngleAxisd rotation(pair.reference_from_input.linear());
    pairs[PairKey(pair)] = {
        {"translation_m", pair.reference_from_input.translation().norm()},
        {"rotation_deg", rotation.angle() * kRadToDeg},
        {"shared_points", c.shared_points},
        {"weakest_std_in_tolerances",
         std::isfinite(c.weakest_std) ? Json(c.weakest_std) : Json()},
        {"weakest_direction", Rounded(c.weakest_direction)},
        {"free_directions", FreeDirections(c)}};
  }
  return pairs;
}

// `dir` may be written: missing, empty, or an earlier simulated set.
bool CheckOutputDir(const std::string& dir, std::string* error) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return true;
  if (!fs::is_directory(dir, ec)) {
    *error = dir + ": exists and is not a folder";
    return false;
  }
  if (fs::is_empty(dir, ec) || fs::exists(dir + "/simulation.json", ec)) {
    return true;
  }
  *error = dir +
           ": a folder that is neither empty nor a simulated data set "
           "(no simulation.json); refusing to write into it";
  return false;
}

}  // namespace

std::string ReferencePairsJson(const SimDataset& dataset) {
  Json root = Json::object();
  for (const SimPair& pair : dataset.pairs) {
    root[PairKey(pair)] = {
        {"reference_from_input", Matrix3x4(pair.reference_from_input)},
        {"prior_from_input", Matrix3x4(pair.reference_from_input)},
        {"spread_m", 0.0},
        {"spread_deg", 0.0},
        {"source", "exact: simulated"},
        {"free_directions", FreeDirections(pair.constraints)}};
  }
  return root.dump(1) + "\n";
}

std::string SimulationJson(const SimDataset& dataset) {
  const SimulationOptions& o = dataset.options;
  Json scene_parameters = Json::object();
  for (const auto& [name, value] : dataset.scene.parameters) {
    scene_parameters[name] = value;
  }
  Json free_world = Json::array();
  for (const Vector3d& axis : dataset.scene.free_translations_world) {
    free_world.push_back(Rounded(axis));
  }
  const PairConstraintOptions& c = o.constraints;
  Json root = {{"format", "mlndt simulated data set, version 1"},
               {"name", SimulationName(o)},
               {"seed", o.seed},
               {"split", o.seed < kFirstTestSeed ? "train" : "test"},
               {"sensor", SensorJson(dataset.sensor)},
               {"scene",
                {{"kind", dataset.scene.kind},
                 {"parameters", scene_parameters},
                 {"triangles", dataset.scene.mesh.num_triangles()},
                 {"free_translations_world", free_world}}},
               {"trajectory", TrajectoryJson(o)},
               {"motion_within_scan", o.motion_within_scan},
               {"beam_offset_deg", o.beam_offset_deg},
               {"steps", o.steps},
               {"constraints",
                {{"tolerance_m", c.tolerance_m},
                 {"tolerance_deg", c.tolerance_deg},
                 {"visibility_m", c.visibility_m},
                 {"max_points", c.max_points}}},
               {"scans", ScansJson(dataset)},
               {"pairs", PairsJson(dataset)}};
  return root.dump(1) + "\n";
}

bool WriteSimDataset(const SimDataset& dataset,
                     const std::string& dir,
                     std::string* error) {
  if (!CheckOutputDir(dir, error)) return false;
  std::error_code ec;
  fs::remove_all(dir + "/pcd", ec);
  fs::create_directories(dir + "/pcd", ec);
  if (ec) {
    *error = dir + "/pcd: cannot create: " + ec.message();
    return false;
  }
  for (size_t k = 0; k < dataset.scans.size(); ++k) {
    if (!WriteSimScanPcd(dir + "/" + ScanFile(k), dataset.scans[k], error)) {
      return false;
    }
  }
  std::string times;
  for (const double stamp : dataset.trajectory.stamps_s) {
    char line[64];
    std::snprintf(line, sizeof(line), "%.9f\n", stamp);
    times += line;
  }
  return WriteKittiPoses(
             dir + "/poses.txt", dataset.trajectory.world_from_sensor, error) &&
         WriteFileAtomically(dir + "/times.txt", times, error) &&
         WriteFileAtomically(dir + "/reference_pairs.json",
                             ReferencePairsJson(dataset),
                             error) &&
         WriteFileAtomically(
             dir + "/simulation.json", SimulationJson(dataset), error);
}

}  // namespace sim
}  // namespace mlndt
