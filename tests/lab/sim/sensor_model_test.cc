// The sensors' scan patterns: the spinning sensors' beam angles and ray
// counts from their data sheets, the rosette's field of view and
// non-repetition, the raster's grid, and the return model's options.

#include "lab/sim/sensor_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {
namespace {

double Elevation(const Eigen::Vector3d& d) {
  return std::atan2(d.z(), d.head<2>().norm()) * kRadToDeg;
}

TEST(SpinningSensor, Vlp16HasSixteenBeamsTwoDegreesApart) {
  SensorModel model;
  ASSERT_TRUE(MakeSensorModel("vlp16", &model));
  std::string error;
  ASSERT_TRUE(model.IsValid(&error)) << error;
  const std::vector<SensorRay> rays = SensorRays(model, 0.0);
  ASSERT_EQ(rays.size(), 1800u * 16u);  // 0.2 deg columns.
  for (int l = 0; l < 16; ++l) {
    EXPECT_NEAR(Elevation(rays[l].direction), -15.0 + 2.0 * l, 1e-9);
    EXPECT_EQ(rays[l].channel, l);
  }
  // Columns 0.2 deg apart in azimuth, one sweep of 0.1 s.
  const double a0 = std::atan2(rays[0].direction.y(), rays[0].direction.x());
  const double a1 = std::atan2(rays[16].direction.y(), rays[16].direction.x());
  EXPECT_NEAR(
      std::abs(std::remainder(a1 - a0, 2 * M_PI)) * kRadToDeg, 0.2, 1e-9);
  EXPECT_EQ(rays.front().time_s, 0.0);
  EXPECT_NEAR(rays.back().time_s, 0.1 * 1799.0 / 1800.0, 1e-12);
  for (const SensorRay& ray : rays) {
    ASSERT_NEAR(ray.direction.norm(), 1.0, 1e-12);
  }
}

TEST(SpinningSensor, Hdl64AndOs1AnglesFollowTheirDataSheets) {
  SensorModel hdl;
  ASSERT_TRUE(MakeSensorModel("hdl64", &hdl));
  const std::vector<double>& a = hdl.spinning.vertical_angles_deg;
  ASSERT_EQ(a.size(), 64u);
  EXPECT_NEAR(*std::min_element(a.begin(), a.end()), -24.33, 1e-9);
  EXPECT_NEAR(*std::max_element(a.begin(), a.end()), 2.0, 1e-9);
  EXPECT_EQ(SensorRays(hdl, 0.0).size(), 64u * 2118u);  // 360 / 0.17.
  SensorModel os1;
  ASSERT_TRUE(MakeSensorModel("os1_64", &os1));
  EXPECT_EQ(SensorRays(os1, 0.0).size(), 64u * 1024u);
  EXPECT_TRUE(SensorCovers(os1, DirectionFromAngles(1.0, 16.0 * kDegToRad)));
  EXPECT_FALSE(SensorCovers(os1, DirectionFromAngles(1.0, 18.0 * kDegToRad)));
}

TEST(RosetteSensor, FillsItsEllipseAndNeverRepeats) {
  SensorModel model;
  ASSERT_TRUE(MakeSensorModel("avia", &model));
  EXPECT_EQ(model.returns.keep_every, 3);
  const std::vector<SensorRay> first = SensorRays(model, 10.0);
  const std::vector<SensorRay> next = SensorRays(model, 10.1);
  ASSERT_EQ(first.size(), 24000u);  // 240k points per second, 0.1 s.
  double max_azimuth = 0, max_elevation = 0;
  for (const SensorRay& ray : first) {
    const Eigen::Vector3d& d = ray.direction;
    max_azimuth =
        std::max(max_azimuth, std::abs(std::atan2(d.y(), d.x())) * kRadToDeg);
    max_elevation = std::max(max_elevation, std::abs(Elevation(d)));
    ASSERT_GT(d.x(), 0.0);
  }
  // 70.4 x 77.2 deg (plus the lasers' +-1.5 deg offsets).
  EXPECT_GT(max_azimuth, 34.0);
  EXPECT_LT(max_azimuth, 35.3);
  EXPECT_GT(max_elevation, 37.5);
  EXPECT_LT(max_elevation, 40.2);
  // The next frame samples other directions.
  size_t same = 0;
  for (size_t k = 0; k < first.size(); ++k) {
    same += (first[k].direction - next[k].direction).norm() < 1e-3 ? 1 : 0;
  }
  EXPECT_LT(same, first.size() / 100);
  EXPECT_TRUE(SensorCovers(model, Eigen::Vector3d(1, 0, 0)));
  EXPECT_FALSE(SensorCovers(model, DirectionFromAngles(0.7, 0.0)));  // 40 deg.
}

TEST(RasterSensor, IsARegularNarrowGrid) {
  SensorModel model;
  ASSERT_TRUE(MakeSensorModel("narrow", &model));
  const std::vector<SensorRay> rays = SensorRays(model, 0.0);
  ASSERT_EQ(rays.size(), 161u * 81u);  // 40 x 20 deg at 0.25 deg.
  EXPECT_NEAR(Elevation(rays.front().direction), 10.0, 1e-9);
  EXPECT_NEAR(Elevation(rays.back().direction), -10.0, 1e-9);
  EXPECT_FALSE(SensorCovers(model, DirectionFromAngles(0.0, 0.2)));
}

TEST(SensorModel, NamesAndOptionChecks) {
  for (const std::string& name : SensorNames()) {
    SensorModel model;
    ASSERT_TRUE(MakeSensorModel(name, &model)) << name;
    std::string error;
    EXPECT_TRUE(model.IsValid(&error)) << name << ": " << error;
  }
  SensorModel model;
  EXPECT_FALSE(MakeSensorModel("vlp32", &model));
  ASSERT_TRUE(MakeSensorModel("vlp16", &model));
  std::string error;
  model.returns.keep_every = 0;
  EXPECT_FALSE(model.IsValid(&error));
  model.returns.keep_every = 1;
  model.returns.max_range_m = 0.5;  // Below min_range_m.
  EXPECT_FALSE(model.IsValid(&error));
  model.returns.max_range_m = 100.0;
  model.spinning.vertical_angles_deg.clear();
  EXPECT_FALSE(model.IsValid(&error));
  EXPECT_NE(error.find("no lasers"), std::string::npos);
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
