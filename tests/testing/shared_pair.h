#pragma once

// One pair of a data folder with a reference_pairs.json and its scans as
// pcd/NNNNNN.pcd (the shared Livox folders): the reference entry and both
// scans; a read failure is a test failure.

#include <string>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/point_cloud.h"

namespace mlndt {
namespace testing {

struct SharedPair {
  ReferencePair pair;
  PointCloud reference;
  PointCloud input;
};

// `key` as in the json ("185_188").
SharedPair ReadSharedPair(const std::string& folder, const std::string& key);

}  // namespace testing
}  // namespace mlndt
