// A simulated data set on disk: the written reference equals the truth
// composed from poses.txt, the reader of the shared sets accepts it, the
// scans read back, the same seed gives the same bytes and another seed
// another scene, a corridor's pairs are free along its axis, and a folder
// that is not a simulated set is left alone.

#include "lab/sim/sim_dataset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lab/eval/reference_pairs.h"
#include "lab/sim/dataset_files.h"
#include "lab/sim/scenes.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "tests/testing/scratch_dir.h"

namespace mlndt {
namespace sim {
namespace {

namespace fs = std::filesystem;

std::string ReadBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream bytes;
  bytes << file.rdbuf();
  return bytes.str();
}

SimulationOptions Small(const std::string& sensor,
                        const std::string& scene,
                        uint64_t seed) {
  SimulationOptions options;
  options.sensor = sensor;
  options.scene = scene;
  options.seed = seed;
  options.num_scans = 3;
  options.steps = {1, 2};
  return options;
}

// Makes and writes the set into the scratch folder `name`.
SimDataset Write(const SimulationOptions& options, const std::string& name) {
  SimDataset dataset;
  std::string error;
  EXPECT_TRUE(MakeSimDataset(options, &dataset, &error)) << error;
  EXPECT_TRUE(WriteSimDataset(dataset, testing::ScratchPath(name), &error))
      << error;
  return dataset;
}

TEST(SimDataset, WrittenReferenceIsTheTruthFromThePoses) {
  const SimDataset dataset = Write(Small("vlp16", "street", 7), "street");
  const std::string dir = testing::ScratchPath("street");
  std::vector<Isometry3d> poses;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(dir + "/poses.txt", &poses, &error)) << error;
  ASSERT_EQ(poses.size(), 3u);
  std::map<std::string, ReferencePair> pairs;
  ASSERT_TRUE(ReadReferencePairs(dir + "/reference_pairs.json", &pairs, &error))
      << error;
  ASSERT_EQ(pairs.size(), 3u);  // 0_1, 1_2, 0_2.
  for (const auto& [key, pair] : pairs) {
    const Isometry3d truth =
        poses[pair.reference_index].inverse() * poses[pair.input_index];
    EXPECT_LT((pair.reference_from_input.matrix() - truth.matrix())
                  .cwiseAbs()
                  .maxCoeff(),
              1e-12)
        << key;
    ASSERT_TRUE(pair.prior_from_input.has_value());
    EXPECT_TRUE(pair.prior_from_input->isApprox(truth, 1e-12));
    EXPECT_EQ(pair.source, "exact: simulated");
    EXPECT_EQ(pair.spread_m, 0.0);
    EXPECT_TRUE(pair.free_directions.empty()) << key;
    // A car step: 1-2 m per scan.
    const double step = pair.input_index - pair.reference_index;
    EXPECT_GT(truth.translation().norm(), 0.9 * step) << key;
    EXPECT_LT(truth.translation().norm(), 2.0 * step) << key;
  }
  for (size_t k = 0; k < 3; ++k) {
    PointCloud cloud;
    char name[32];
    std::snprintf(name, sizeof(name), "/pcd/%06zu.pcd", k);
    ASSERT_TRUE(ReadPointCloud(dir + name, &cloud, nullptr, &error)) << error;
    ASSERT_EQ(cloud.size(), dataset.scans[k].points.size());
    EXPECT_GT(cloud.size(), 10000u);
    EXPECT_NEAR((cloud[5] - dataset.scans[k].points[5]).norm(), 0.0, 1e-5);
  }
}

TEST(SimDataset, SameSeedSameBytesOtherSeedOtherScene) {
  Write(Small("avia", "rooms", 1001), "a");
  Write(Small("avia", "rooms", 1001), "b");
  Write(Small("avia", "rooms", 1002), "c");
  for (const char* file : {"/pcd/000000.pcd",
                           "/pcd/000002.pcd",
                           "/poses.txt",
                           "/times.txt",
                           "/reference_pairs.json",
                           "/simulation.json"}) {
    const std::string a = ReadBytes(testing::ScratchPath("a") + file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, ReadBytes(testing::ScratchPath("b") + file)) << file;
    EXPECT_NE(a, ReadBytes(testing::ScratchPath("c") + file)) << file;
  }
  Scene one, other;
  std::string error;
  ASSERT_TRUE(BuildScene("street", 1001, &one, &error));
  ASSERT_TRUE(BuildScene("street", 1002, &other, &error));
  EXPECT_NE(one.parameters, other.parameters);
  EXPECT_NE(one.mesh.vertices.size() == other.mesh.vertices.size() &&
                std::equal(one.mesh.vertices.begin(),
                           one.mesh.vertices.end(),
                           other.mesh.vertices.begin()),
            true);
}

TEST(SimDataset, CorridorPairsAreFreeAlongItsAxisOnly) {
  SimulationOptions options = Small("os1_64", "corridor", 11);
  const SimDataset dataset = Write(options, "corridor");
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      testing::ScratchPath("corridor") + "/reference_pairs.json",
      &pairs,
      &error))
      << error;
  for (const auto& [key, pair] : pairs) {
    ASSERT_EQ(pair.free_directions.size(), 1u) << key;
    const Vector6d& free = pair.free_directions[0];
    // The world's x axis in the reference frame, no rotation.
    const Vector3d axis =
        dataset.trajectory.world_from_sensor[pair.reference_index]
            .linear()
            .transpose() *
        Vector3d::UnitX();
    EXPECT_NEAR(std::abs(free.head<3>().dot(axis)), 1.0, 1e-9) << key;
    EXPECT_NEAR(free.tail<3>().norm(), 0.0, 1e-12) << key;
  }
  // The Cramér-Rao bound along the axis is unbounded; every other direction
  // is held to well within the tolerance.
  for (const SimPair& pair : dataset.pairs) {
    EXPECT_GT(pair.constraints.weakest_std, 100.0);
    EXPECT_GT(pair.constraints.shared_points, 1000u);
  }
}

TEST(SimDataset, RefusesAFolderThatIsNotASimulatedSet) {
  const std::string dir = testing::ScratchPath("foreign");
  fs::create_directories(dir);
  std::ofstream(dir + "/notes.txt") << "keep me";
  SimDataset dataset;
  std::string error;
  ASSERT_TRUE(MakeSimDataset(Small("narrow", "field", 3), &dataset, &error))
      << error;
  EXPECT_FALSE(WriteSimDataset(dataset, dir, &error));
  EXPECT_NE(error.find("refusing"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(dir + "/pcd"));
  EXPECT_EQ(ReadBytes(dir + "/notes.txt"), "keep me");
}

// Elevation of every point of laser `channel` in scan `k` [deg].
std::vector<double> ChannelElevationsDeg(const SimDataset& dataset,
                                         size_t k,
                                         int channel) {
  std::vector<double> elevations;
  const SimScan& scan = dataset.scans.at(k);
  for (size_t i = 0; i < scan.points.size(); ++i) {
    if (scan.channels[i] != channel) continue;
    const Vector3d& p = scan.points[i];
    elevations.push_back(std::atan2(p.z(), p.head<2>().norm()) * 180.0 / M_PI);
  }
  return elevations;
}

TEST(SimDataset, BeamOffsetShiftsEachScansRingsAndNothingElse) {
  SimulationOptions options = Small("vlp16", "street", 2);
  SimDataset plain, shifted;
  std::string error;
  ASSERT_TRUE(MakeSimDataset(options, &plain, &error)) << error;
  options.beam_offset_deg = 1.0;
  ASSERT_TRUE(MakeSimDataset(options, &shifted, &error)) << error;
  std::vector<double> offsets_deg;
  for (size_t k = 0; k < plain.scans.size(); ++k) {
    EXPECT_TRUE(shifted.trajectory.world_from_sensor[k].isApprox(
        plain.trajectory.world_from_sensor[k], 0.0));
    // The VLP-16's lowest laser is at -15 deg; the noise is along the ray.
    for (const double e : ChannelElevationsDeg(plain, k, 0)) {
      ASSERT_NEAR(e, -15.0, 1e-6);
    }
    const std::vector<double> e = ChannelElevationsDeg(shifted, k, 0);
    ASSERT_FALSE(e.empty());
    for (const double v : e) ASSERT_NEAR(v, e.front(), 1e-6);
    offsets_deg.push_back(e.front() + 15.0);
    EXPECT_LE(std::abs(offsets_deg.back()), 1.0);
    EXPECT_GT(std::abs(offsets_deg.back()), 1e-6);
  }
  EXPECT_GT(std::abs(offsets_deg[0] - offsets_deg[1]), 1e-6);
}

TEST(SimDataset, BadOptionsAreRefused) {
  SimDataset dataset;
  std::string error;
  SimulationOptions options = Small("vlp16", "street", 1);
  options.sensor = "lidar9000";
  EXPECT_FALSE(MakeSimDataset(options, &dataset, &error));
  EXPECT_NE(error.find("lidar9000"), std::string::npos);
  options = Small("vlp16", "moon", 1);
  EXPECT_FALSE(MakeSimDataset(options, &dataset, &error));
  options = Small("vlp16", "street", 1);
  options.num_scans = 1;
  EXPECT_FALSE(MakeSimDataset(options, &dataset, &error));
  options = Small("vlp16", "street", 1);
  options.trajectory = "bicycle";
  EXPECT_FALSE(MakeSimDataset(options, &dataset, &error));
  options = Small("vlp16", "street", 1);
  options.beam_offset_deg = 11.0;
  EXPECT_FALSE(MakeSimDataset(options, &dataset, &error));
  EXPECT_NE(error.find("beam_offset_deg"), std::string::npos);
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
