// Free directions from what a pair sees: a single wall leaves the two
// translations along it and the rotation about its normal free; a box
// room constrains everything; a scene's own free axis is named first.

#include "lab/sim/pair_constraints.h"

#include <gtest/gtest.h>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_trajectory.h"

namespace mlndt {
namespace sim {
namespace {

struct PairSetup {
  Scene scene;
  std::unique_ptr<RayCaster> caster;
  SensorModel sensor;
  Isometry3d reference = Isometry3d::Identity();
  Isometry3d input = Isometry3d::Identity();
  SimScan scan;
};

void Render(PairSetup* s) {
  std::string error;
  s->caster = RayCaster::Create(s->scene.mesh, &error);
  ASSERT_NE(s->caster, nullptr) << error;
  ASSERT_TRUE(MakeSensorModel("narrow", &s->sensor));
  s->reference = PoseFromYawPitchRoll(Vector3d(0, 0, 1.5), 0.0, 0.0, 0.0);
  s->input = PoseFromYawPitchRoll(Vector3d(0.2, 0.1, 1.5), 0.05, 0.0, 0.0);
  ScanMotion motion;
  motion.world_from_sensor = s->input;
  RenderScan(
      *s->caster, s->sensor, SensorRays(s->sensor, 0.0), motion, 5, &s->scan);
  ASSERT_GT(s->scan.points.size(), 5000u);
}

TEST(PairConstraints, AWallLeavesThreeDirectionsFree) {
  PairSetup s;
  // The wall x = 6 facing the narrow sensor (nothing else in view).
  s.scene.mesh.AddQuad(Vector3d(6, -50, -50),
                       Vector3d(6, 50, -50),
                       Vector3d(6, 50, 50),
                       Vector3d(6, -50, 50));
  Render(&s);
  const PairConstraints c = AnalysePairConstraints(PairConstraintOptions(),
                                                   *s.caster,
                                                   s.sensor,
                                                   s.scene,
                                                   s.reference,
                                                   s.input,
                                                   s.scan);
  EXPECT_GT(c.shared_points, 5000u);
  ASSERT_EQ(c.free_directions.size(), 3u);
  // They span y, z translation and the rotation about the normal x
  // (alpha): nothing of x translation, beta or gamma.
  Eigen::Matrix<double, 6, 3> basis;
  for (int k = 0; k < 3; ++k) basis.col(k) = c.free_directions[k];
  for (const int constrained : {0, 4, 5}) {
    EXPECT_LT(basis.row(constrained).norm(), 0.05) << constrained;
  }
}

TEST(PairConstraints, ABoxRoomConstrainsEverything) {
  PairSetup s;
  AddBox(Vector3d(-5, -4, 0), Vector3d(5, 4, 3), &s.scene.mesh);
  // The narrow sensor needs corners: turn the reference and input to look
  // at one.
  Render(&s);
  s.reference = PoseFromYawPitchRoll(Vector3d(0, 0, 1.5), 0.6, -0.2, 0.0);
  s.input = PoseFromYawPitchRoll(Vector3d(0.1, 0.1, 1.5), 0.62, -0.2, 0.0);
  ScanMotion motion;
  motion.world_from_sensor = s.input;
  RenderScan(
      *s.caster, s.sensor, SensorRays(s.sensor, 0.0), motion, 5, &s.scan);
  const PairConstraints c = AnalysePairConstraints(PairConstraintOptions(),
                                                   *s.caster,
                                                   s.sensor,
                                                   s.scene,
                                                   s.reference,
                                                   s.input,
                                                   s.scan);
  EXPECT_TRUE(c.free_directions.empty());
  EXPECT_LT(c.weakest_std, 0.5);
  // A scene that declares x free is free along x, in the reference frame.
  s.scene.free_translations_world = {Vector3d::UnitX()};
  const PairConstraints declared =
      AnalysePairConstraints(PairConstraintOptions(),
                             *s.caster,
                             s.sensor,
                             s.scene,
                             s.reference,
                             s.input,
                             s.scan);
  ASSERT_EQ(declared.free_directions.size(), 1u);
  const Vector3d expected =
      s.reference.linear().transpose() * Vector3d::UnitX();
  EXPECT_LT((declared.free_directions[0].head<3>() - expected).norm(), 1e-12);
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
