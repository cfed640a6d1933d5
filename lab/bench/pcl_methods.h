#pragma once

// PCL's registrations as mlndt_bench methods, in the build configured with
// -DMLNDT_WITH_PCL=ON (Debian 12's PCL 1.13); without it PclAvailable() is
// false and the factories return null.
//
// Both run on clouds converted to pcl::PointXYZ once, untimed (Prepare), and
// filtered by a pcl::VoxelGrid (leaf_size_m, gicp_leaf_size_m) inside the
// timing: a
// method's time covers filtering, setInputTarget/setInputSource and align(),
// i.e. everything after loading, like mlndt's time_ms.total.
//
// pcl_ndt, pcl::NormalDistributionsTransform: 1.0 m cells as its peers
// (PEERS.md 1a), at most 35 iterations, step size 1.0 and transformation
// epsilon 1e-4, the PCL setting that reached the pairs' answers in our sweep
// (docs/performance.md). The peers' and PCL tutorial's step 0.1 and epsilon
// 0.01 are a different thing since PCL PR #1724 (2017): NDT compares epsilon
// with the step's *squared* translation, so with steps capped at 0.1 m PCL
// stops after its first step (0.41 m short on the koide3 pair).
//
// pcl_gicp, pcl::GeneralizedIterativeClosestPoint set up as the peer
// harness of issue 45 (the proxy of the fastest peers): 0.25 m leaves,
// correspondences within 1 m, PCL 1.13's other defaults (20 neighbours per
// covariance, at most 200 iterations, transformation epsilon 5e-4; the leaf,
// the distance and the cap are options). PCL reports convergence at the cap
// too; `converged` here means it stopped before the cap. Both PCL methods are
// single-threaded.

#include <memory>

#include "lab/bench/bench_method.h"
#include "lab/bench/pcl_bench_options.h"

namespace mlndt {

// True in the build with PCL.
bool PclAvailable();

// The methods; null without PCL.
std::unique_ptr<BenchMethod> MakePclNdtMethod(const PclBenchOptions& options);
std::unique_ptr<BenchMethod> MakePclGicpMethod(const PclBenchOptions& options);

}  // namespace mlndt
