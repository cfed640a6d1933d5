#include "tests/testing/koide3_pair.h"

#include <glog/logging.h>

#include <string>

#include "mlndt/cloud/io.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace testing {

const Koide3MapAndSamples& Koide3Pair() {
  static const Koide3MapAndSamples* pair = [] {
    auto* p = new Koide3MapAndSamples;
    PointCloud reference, input, sampled;
    std::string error;
    CHECK(ReadPointCloud(
        BundledDataPath("koide3/251370668.pcd"), &reference, nullptr, &error))
        << error;
    CHECK(ReadPointCloud(
        BundledDataPath("koide3/251371071.pcd"), &input, nullptr, &error))
        << error;
    CHECK(LayeredGrid::Build(LayeredGridOptions(), reference, &p->map, &error))
        << error;
    CHECK(SamplePoints(SamplingOptions(), input, &sampled, nullptr, &error))
        << error;
    p->samples = sampled.points();
    return p;
  }();
  return *pair;
}

}  // namespace testing
}  // namespace mlndt
