// mlndt::pcl::MultiLayerNdt against mlndt::Register on the bundled pairs:
// the same pose bit for bit, hasConverged() only for CONVERGENCE, the PCL
// setters mapped onto mlndt's options, the map built once per target, and
// bad input refused without a result.

#include "mlndt/pcl/multi_layer_ndt.h"

#include <glog/logging.h>
#include <gtest/gtest.h>
#include <pcl/common/transforms.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/pcl/conversions.h"
#include "mlndt/registration/registration.h"

// Every member of the class template, for the point types of the tests.
template class mlndt::pcl::MultiLayerNdt<pcl::PointXYZ, pcl::PointXYZ>;
template class mlndt::pcl::MultiLayerNdt<pcl::PointXYZI, pcl::PointXYZI>;
template class mlndt::pcl::MultiLayerNdt<pcl::PointXYZI, pcl::PointXYZ>;

namespace mlndt {
namespace pcl {
namespace {

using ::pcl::PointXYZ;
using ::pcl::PointXYZI;
using Ndt = MultiLayerNdt<PointXYZ, PointXYZ>;
using CloudXYZ = ::pcl::PointCloud<PointXYZ>;

const std::string kDataDir = MLNDT_PCL_TEST_DATA_DIR;

// A pair of the bundled data: reference (PCL's target) and input (source)
// files, and its reference_from_input in reference_pairs.json.
struct Pair {
  std::string name;
  std::string folder;
  std::string reference;
  std::string input;
  std::string key;
};

const std::vector<Pair>& Pairs() {
  static const std::vector<Pair> pairs = {
      {"koide3",
       "koide3",
       "251370668.pcd",
       "251371071.pcd",
       "251370668_251371071"},
      {"kitti_0_1", "kitti", "pcd/000000.pcd", "pcd/000001.pcd", "0_1"},
      {"kitti_3_4", "kitti", "pcd/000003.pcd", "pcd/000004.pcd", "3_4"},
      {"kitti_0_5", "kitti", "pcd/000000.pcd", "pcd/000005.pcd", "0_5"},
      {"room", "room", "room_scan1.pcd", "room_scan2.pcd", "1_2"},
  };
  return pairs;
}

std::string PathOf(const Pair& pair, const std::string& file) {
  return kDataDir + "/" + pair.folder + "/" + file;
}

// `key`'s reference_from_input (row-major 3x4) in the folder's
// reference_pairs.json.
Isometry3d ReadReference(const Pair& pair) {
  std::ifstream file(PathOf(pair, "reference_pairs.json"));
  std::stringstream text;
  text << file.rdbuf();
  const std::string json = text.str();
  size_t at = json.find("\"" + pair.key + "\"");
  at = json.find("\"reference_from_input\"", at);
  at = json.find('[', at);
  CHECK(at != std::string::npos) << pair.name << ": no reference";
  Isometry3d transform = Isometry3d::Identity();
  const char* cursor = json.c_str() + at + 1;
  for (int i = 0; i < 12; ++i) {
    char* end = nullptr;
    transform.matrix()(i / 4, i % 4) = std::strtod(cursor, &end);
    CHECK(end != cursor) << pair.name << ": bad reference";
    cursor = end + 1;  // Past the ','.
  }
  return transform;
}

template <typename PointT>
typename ::pcl::PointCloud<PointT>::Ptr LoadPcl(const std::string& path) {
  typename ::pcl::PointCloud<PointT>::Ptr cloud(new ::pcl::PointCloud<PointT>);
  CHECK_EQ(::pcl::io::loadPCDFile(path, *cloud), 0) << path;
  return cloud;
}

PointCloud LoadMlndt(const std::string& path) {
  PointCloud cloud;
  std::string error;
  CHECK(ReadPointCloud(path, &cloud, nullptr, &error)) << error;
  return cloud;
}

Isometry3d ToIsometryOrDie(const Eigen::Matrix4f& matrix) {
  Isometry3d transform;
  std::string error;
  CHECK(ToIsometry(matrix, &transform, &error)) << error;
  return transform;
}

// The start 5 m along the reference frame's x and 30 deg of yaw from the
// reference: offset ∘ reference.
Eigen::Matrix4f FarStart(const Isometry3d& reference) {
  const Isometry3d offset = PoseVectorToIsometry(
      PoseVectorFromDegrees(5.0, 0.0, 0.0, 0.0, 0.0, 30.0));
  return (offset * reference).matrix().cast<float>();
}

bool SameBits(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 16) == 0;
}

bool SameBits(const Matrix6d& a, const Matrix6d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 36) == 0;
}

// Adapter and Register on the same files, options and guess.
void ExpectSameAsRegister(const Pair& pair,
                          const Eigen::Matrix4f& guess,
                          const RegistrationOptions& options) {
  const CloudXYZ::Ptr target = LoadPcl<PointXYZ>(PathOf(pair, pair.reference));
  const CloudXYZ::Ptr source = LoadPcl<PointXYZ>(PathOf(pair, pair.input));
  Ndt ndt;
  ndt.setOptions(options);
  ndt.setInputTarget(target);
  ndt.setInputSource(source);
  CloudXYZ aligned;
  ndt.align(aligned, guess);

  RegistrationSummary expected;
  Register(options,
           LoadMlndt(PathOf(pair, pair.reference)),
           LoadMlndt(PathOf(pair, pair.input)),
           ToIsometryOrDie(guess),
           &expected);
  const RegistrationSummary& summary = ndt.getSummary();
  EXPECT_TRUE(SameBits(summary.reference_from_input.matrix(),
                       expected.reference_from_input.matrix()))
      << "adapter:\n"
      << summary.reference_from_input.matrix() << "\nRegister:\n"
      << expected.reference_from_input.matrix();
  EXPECT_EQ(summary.termination_type, expected.termination_type);
  EXPECT_EQ(summary.message, expected.message);
  EXPECT_EQ(summary.num_iterations, expected.num_iterations);
  EXPECT_EQ(summary.final_score, expected.final_score);
  EXPECT_TRUE(SameBits(summary.covariance, expected.covariance));
  EXPECT_EQ(
      ndt.getFinalTransformation(),
      Eigen::Matrix4f(expected.reference_from_input.matrix().cast<float>()));
  EXPECT_EQ(ndt.hasConverged(),
            expected.termination_type == TerminationType::CONVERGENCE);
  EXPECT_EQ(ndt.getFinalNumIteration(), expected.num_iterations);
  CloudXYZ moved;
  ::pcl::transformPointCloud(*source, moved, ndt.getFinalTransformation());
  ASSERT_EQ(aligned.size(), moved.size());
  for (size_t i = 0; i < moved.size(); ++i) {
    ASSERT_EQ(aligned[i].getVector3fMap(), moved[i].getVector3fMap()) << i;
  }
}

class SameAsRegister : public testing::TestWithParam<std::tuple<size_t, bool>> {
};

TEST_P(SameAsRegister, PoseVerdictAndCovarianceBitForBit) {
  const Pair& pair = Pairs()[std::get<0>(GetParam())];
  const bool far = std::get<1>(GetParam());
  const Eigen::Matrix4f guess =
      far ? FarStart(ReadReference(pair)) : Eigen::Matrix4f::Identity();
  ExpectSameAsRegister(pair, guess, RegistrationOptions());
}

INSTANTIATE_TEST_SUITE_P(
    Pairs,
    SameAsRegister,
    testing::Combine(testing::Range<size_t>(0, 5), testing::Bool()),
    [](const testing::TestParamInfo<SameAsRegister::ParamType>& info) {
      return Pairs()[std::get<0>(info.param)].name +
             (std::get<1>(info.param) ? "_far_start" : "_identity");
    });

// PCL's tutorial settings reach mlndt as the options they map to.
TEST(MultiLayerNdt, TutorialSettingsAreTheMappedOptions) {
  const Pair& room = Pairs()[4];
  const CloudXYZ::Ptr target = LoadPcl<PointXYZ>(PathOf(room, room.reference));
  const CloudXYZ::Ptr source = LoadPcl<PointXYZ>(PathOf(room, room.input));
  const Eigen::Matrix4f guess =
      (Eigen::Translation3f(1.79387f, 0.720047f, 0.0f) *
       Eigen::AngleAxisf(0.6931f, Eigen::Vector3f::UnitZ()))
          .matrix();
  Ndt ndt;
  ndt.setTransformationEpsilon(0.01);
  ndt.setStepSize(0.1);
  ndt.setResolution(1.0f);
  ndt.setMaximumIterations(35);
  ndt.setInputSource(source);
  ndt.setInputTarget(target);
  CloudXYZ aligned;
  ndt.align(aligned, guess);

  // The tutorial's epsilon (0.01 m^2: 0.1 m steps) is looser than mlndt's
  // step tolerance and is not applied; its step size has no meaning here.
  RegistrationOptions options;
  options.grid.finest_cell_size_m = 1.0;
  options.schedule.max_final_iterations = 35;
  RegistrationSummary expected;
  Register(options,
           LoadMlndt(PathOf(room, room.reference)),
           LoadMlndt(PathOf(room, room.input)),
           ToIsometryOrDie(guess),
           &expected);
  EXPECT_TRUE(SameBits(ndt.getSummary().reference_from_input.matrix(),
                       expected.reference_from_input.matrix()));
  EXPECT_EQ(ndt.getSummary().termination_type, expected.termination_type);
  EXPECT_DOUBLE_EQ(ndt.getStepSize(), 0.1);
}

TEST(MultiLayerNdt, PclSettersMapOntoTheOptions) {
  Ndt ndt;
  const RegistrationOptions defaults;
  EXPECT_EQ(ndt.getMaximumIterations(), defaults.schedule.max_final_iterations);
  EXPECT_EQ(ndt.getResolution(),
            static_cast<float>(defaults.grid.finest_cell_size_m));
  EXPECT_EQ(ndt.getOptions().schedule.step_tolerance,
            defaults.schedule.step_tolerance);

  ndt.setMaximumIterations(12);
  ndt.setTransformationEpsilon(4e-8);
  ndt.setResolution(0.75f);
  ndt.setMinPointPerVoxel(7);
  ndt.setNumThreads(2);
  ndt.setOulierRatio(0.3);
  RegistrationOptions options = ndt.getOptions();
  EXPECT_EQ(options.schedule.max_final_iterations, 12);
  EXPECT_DOUBLE_EQ(options.schedule.step_tolerance, 2e-4);
  EXPECT_EQ(options.grid.finest_cell_size_m, 0.75);
  EXPECT_EQ(options.grid.min_points_per_cell, 7);
  EXPECT_EQ(options.num_threads, 2);
  EXPECT_EQ(ndt.getOulierRatio(), 0.3);

  // A looser bound than the options' and PCL's "not set" keep the options'
  // tolerance.
  for (const double epsilon : {0.01, 0.0, -1.0}) {
    ndt.setTransformationEpsilon(epsilon);
    EXPECT_EQ(ndt.getOptions().schedule.step_tolerance,
              defaults.schedule.step_tolerance);
  }

  // setOptions sets the PCL members too, and reads back unchanged.
  options = RegistrationOptions();
  options.schedule.max_final_iterations = 44;
  options.schedule.step_tolerance = 3e-4;
  options.sampling.voxel_size_m *= 2.0;
  ndt.setOptions(options);
  EXPECT_EQ(ndt.getMaximumIterations(), 44);
  EXPECT_DOUBLE_EQ(ndt.getTransformationEpsilon(), 9e-8);
  EXPECT_EQ(ndt.getOptions().schedule.step_tolerance, 3e-4);
  EXPECT_EQ(ndt.getOptions().sampling.voxel_size_m,
            options.sampling.voxel_size_m);
}

// A start mlndt does not recover from today (the pose lands > 0.5 m off):
// the verdict is not CONVERGENCE and hasConverged() says false. If mlndt
// ever lands right from here, pick a farther start.
TEST(MultiLayerNdt, HasConvergedIsFalseOnAKnownWrongStart) {
  const Pair& koide3 = Pairs()[0];
  const Isometry3d reference = ReadReference(koide3);
  const CloudXYZ::Ptr target =
      LoadPcl<PointXYZ>(PathOf(koide3, koide3.reference));
  const CloudXYZ::Ptr source = LoadPcl<PointXYZ>(PathOf(koide3, koide3.input));
  Ndt ndt;
  ndt.setInputTarget(target);
  ndt.setInputSource(source);
  CloudXYZ aligned;
  ndt.align(aligned, FarStart(reference));
  const Isometry3d wrong = ndt.getSummary().reference_from_input;
  ASSERT_GT(TranslationErrorM(wrong, reference), 0.5);
  EXPECT_NE(ndt.getSummary().termination_type, TerminationType::CONVERGENCE);
  EXPECT_NE(ndt.getSummary().termination_type, TerminationType::FAILURE);
  EXPECT_FALSE(ndt.hasConverged());
  const double wrong_fitness = ndt.getFitnessScore();

  // From the identity the same object lands right and says so; PCL's
  // fitness score tells the two apart as well.
  ndt.align(aligned);
  const Isometry3d right = ndt.getSummary().reference_from_input;
  EXPECT_LT(TranslationErrorM(right, reference), 0.05);
  EXPECT_TRUE(ndt.hasConverged());
  EXPECT_LT(ndt.getFitnessScore(), wrong_fitness);
}

// The solver's flag is not the verdict: the iteration cap gives a pose
// Register also gives, and hasConverged() false.
TEST(MultiLayerNdt, IterationCapIsNotConvergence) {
  const Pair& kitti = Pairs()[1];
  RegistrationOptions options;
  options.schedule.max_final_iterations = 1;
  options.schedule.step_tolerance = 1e-9;
  ExpectSameAsRegister(kitti, Eigen::Matrix4f::Identity(), options);

  const CloudXYZ::Ptr target =
      LoadPcl<PointXYZ>(PathOf(kitti, kitti.reference));
  const CloudXYZ::Ptr source = LoadPcl<PointXYZ>(PathOf(kitti, kitti.input));
  Ndt ndt;
  ndt.setMaximumIterations(1);
  ndt.setTransformationEpsilon(1e-18);
  ndt.setInputTarget(target);
  ndt.setInputSource(source);
  CloudXYZ aligned;
  ndt.align(aligned);
  EXPECT_NE(ndt.getSummary().termination_type, TerminationType::CONVERGENCE);
  EXPECT_FALSE(ndt.hasConverged());
}

TEST(MultiLayerNdt, MapIsBuiltOncePerTarget) {
  const Pair& koide3 = Pairs()[0];
  const CloudXYZ::Ptr target =
      LoadPcl<PointXYZ>(PathOf(koide3, koide3.reference));
  const CloudXYZ::Ptr source = LoadPcl<PointXYZ>(PathOf(koide3, koide3.input));
  Ndt ndt;
  EXPECT_TRUE(ndt.getTargetMap().empty());
  ndt.setInputTarget(target);  // Builds the map.
  const int layers = ndt.getTargetMap().num_layers();
  ASSERT_GT(layers, 0);
  ndt.setInputSource(source);
  CloudXYZ aligned;
  ndt.align(aligned);
  const RegistrationSummary first = ndt.getSummary();
  EXPECT_EQ(first.map_time_s, 0.0);  // align() did not build it.
  EXPECT_TRUE(first.IsSolutionUsable());

  ndt.align(aligned);
  EXPECT_EQ(ndt.getSummary().map_time_s, 0.0);
  EXPECT_TRUE(SameBits(ndt.getSummary().reference_from_input.matrix(),
                       first.reference_from_input.matrix()));

  // A map option changed after the build: rebuilt at the next align().
  ndt.setResolution(4.0f);
  EXPECT_EQ(ndt.getTargetMap().num_layers(), layers);
  ndt.align(aligned);
  EXPECT_GT(ndt.getSummary().map_time_s, 0.0);
  EXPECT_LT(ndt.getTargetMap().num_layers(), layers);
  EXPECT_LE(ndt.getTargetMap().layer_info().back().cell_size_m, 4.0);
  ndt.align(aligned);
  EXPECT_EQ(ndt.getSummary().map_time_s, 0.0);

  // An option the map does not depend on: no rebuild.
  ndt.setMaximumIterations(40);
  ndt.align(aligned);
  EXPECT_EQ(ndt.getSummary().map_time_s, 0.0);
}

// A converged result first, so that a stale one would show.
void AlignRight(Ndt* ndt, CloudXYZ* aligned) {
  const Pair& koide3 = Pairs()[0];
  ndt->setInputTarget(LoadPcl<PointXYZ>(PathOf(koide3, koide3.reference)));
  ndt->setInputSource(LoadPcl<PointXYZ>(PathOf(koide3, koide3.input)));
  ndt->align(*aligned);
  ASSERT_TRUE(ndt->hasConverged());
}

TEST(MultiLayerNdt, BadSettingsFailWithTheGuessAsResult) {
  const Eigen::Matrix4f guess =
      (Eigen::Translation3f(0.3f, 0.1f, 0.0f) *
       Eigen::AngleAxisf(0.02f, Eigen::Vector3f::UnitZ()))
          .matrix();
  struct Case {
    std::string expected_message;
    std::function<void(Ndt*)> set;
  };
  const std::vector<Case> cases = {
      {"setTransformationEpsilon",
       [](Ndt* ndt) { ndt->setTransformationEpsilon(NAN); }},
      {"setTransformationEpsilon",
       [](Ndt* ndt) { ndt->setTransformationEpsilon(1e-30); }},
      {"setMaximumIterations", [](Ndt* ndt) { ndt->setMaximumIterations(0); }},
      {"num_threads", [](Ndt* ndt) { ndt->setNumThreads(0); }},
      {"finest_cell_size_m", [](Ndt* ndt) { ndt->setResolution(1e6f); }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expected_message);
    Ndt ndt;
    CloudXYZ aligned;
    AlignRight(&ndt, &aligned);
    c.set(&ndt);
    ndt.align(aligned, guess);
    EXPECT_EQ(ndt.getSummary().termination_type, TerminationType::FAILURE);
    EXPECT_NE(ndt.getSummary().message.find(c.expected_message),
              std::string::npos)
        << ndt.getSummary().message;
    EXPECT_FALSE(ndt.hasConverged());
    EXPECT_EQ(ndt.getFinalTransformation(), guess);
  }
}

TEST(MultiLayerNdt, NonRigidGuessFails) {
  Ndt ndt;
  CloudXYZ aligned;
  AlignRight(&ndt, &aligned);
  Eigen::Matrix4f scaled = Eigen::Matrix4f::Identity();
  scaled(0, 0) = 2.0f;
  ndt.align(aligned, scaled);
  EXPECT_EQ(ndt.getSummary().termination_type, TerminationType::FAILURE);
  EXPECT_NE(ndt.getSummary().message.find("the guess"), std::string::npos);
  EXPECT_FALSE(ndt.hasConverged());
}

TEST(MultiLayerNdt, RefusedInputsClearTheResult) {
  const CloudXYZ::Ptr empty(new CloudXYZ);
  {
    Ndt ndt;
    CloudXYZ aligned;
    AlignRight(&ndt, &aligned);
    ndt.setInputSource(empty);
    EXPECT_FALSE(ndt.hasConverged());
    ndt.align(aligned);  // pcl::Registration refuses: no source.
    EXPECT_FALSE(ndt.hasConverged());
    EXPECT_EQ(ndt.getSummary().termination_type, TerminationType::FAILURE);
  }
  {
    Ndt ndt;
    CloudXYZ aligned;
    AlignRight(&ndt, &aligned);
    ndt.setInputTarget(empty);
    EXPECT_FALSE(ndt.hasConverged());
    ndt.align(aligned);  // pcl::Registration refuses: no target.
    EXPECT_FALSE(ndt.hasConverged());
    EXPECT_TRUE(ndt.getTargetMap().empty());
  }
}

TEST(MultiLayerNdt, NonFinitePointsAreDropped) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Pair& koide3 = Pairs()[0];
  const CloudXYZ::Ptr target =
      LoadPcl<PointXYZ>(PathOf(koide3, koide3.reference));
  const CloudXYZ::Ptr source = LoadPcl<PointXYZ>(PathOf(koide3, koide3.input));
  CloudXYZ::Ptr holed(new CloudXYZ);
  for (size_t i = 0; i < source->size(); ++i) {
    holed->push_back((*source)[i]);
    if (i % 100 == 0) holed->push_back(PointXYZ(nan, nan, nan));
  }
  holed->is_dense = false;
  Ndt plain, with_holes;
  CloudXYZ aligned;
  plain.setInputTarget(target);
  plain.setInputSource(source);
  plain.align(aligned);
  with_holes.setInputTarget(target);
  with_holes.setInputSource(holed);
  with_holes.align(aligned);
  EXPECT_EQ(with_holes.getSourceDroppedNonFinite(),
            (source->size() + 99) / 100);
  EXPECT_TRUE(SameBits(with_holes.getSummary().reference_from_input.matrix(),
                       plain.getSummary().reference_from_input.matrix()));

  CloudXYZ::Ptr all_nan(new CloudXYZ);
  all_nan->push_back(PointXYZ(nan, 0.0f, 0.0f));
  all_nan->is_dense = false;
  Ndt no_target;
  no_target.setInputTarget(all_nan);
  no_target.setInputSource(source);
  no_target.align(aligned);
  EXPECT_EQ(no_target.getSummary().termination_type, TerminationType::FAILURE);
  EXPECT_NE(no_target.getSummary().message.find("no finite point"),
            std::string::npos)
      << no_target.getSummary().message;
  EXPECT_FALSE(no_target.hasConverged());
}

// PointXYZI (the koide3 files have intensity): the same pose as PointXYZ,
// also through a pcl::Registration pointer.
TEST(MultiLayerNdt, PointXYZIGivesThePointXYZPose) {
  const Pair& koide3 = Pairs()[0];
  using Registration = ::pcl::Registration<PointXYZI, PointXYZI, float>;
  Registration::Ptr registration(new MultiLayerNdt<PointXYZI, PointXYZI>);
  registration->setInputTarget(
      LoadPcl<PointXYZI>(PathOf(koide3, koide3.reference)));
  registration->setInputSource(
      LoadPcl<PointXYZI>(PathOf(koide3, koide3.input)));
  ::pcl::PointCloud<PointXYZI> aligned;
  registration->align(aligned);

  Ndt xyz;
  xyz.setInputTarget(LoadPcl<PointXYZ>(PathOf(koide3, koide3.reference)));
  xyz.setInputSource(LoadPcl<PointXYZ>(PathOf(koide3, koide3.input)));
  CloudXYZ aligned_xyz;
  xyz.align(aligned_xyz);
  EXPECT_TRUE(xyz.hasConverged());
  EXPECT_EQ(registration->hasConverged(), xyz.hasConverged());
  EXPECT_EQ(registration->getFinalTransformation(),
            xyz.getFinalTransformation());
  EXPECT_EQ(registration->getFitnessScore(), xyz.getFitnessScore());
}

}  // namespace
}  // namespace pcl
}  // namespace mlndt
