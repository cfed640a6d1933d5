#include "tests/testing/street_pair.h"

#include <glog/logging.h>

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/pose.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace testing {

const StreetPair& Street() {
  static const StreetPair* pair = [] {
    auto* p = new StreetPair;
    std::string error;
    CHECK(LayeredGrid::Build(
        LayeredGridOptions(), StreetScene(20000, 0.02, 1), &p->map, &error))
        << error;
    const Vector6d offset = PoseVectorFromDegrees(0.4, -0.3, 0.1, 0, 0, 2);
    p->input = TransformCloud(PoseVectorToIsometry(offset).inverse(),
                              StreetScene(3000, 0.02, 2))
                   .points();
    return p;
  }();
  return *pair;
}

}  // namespace testing
}  // namespace mlndt
