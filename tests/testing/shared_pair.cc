#include "tests/testing/shared_pair.h"

#include <gtest/gtest.h>

#include <map>

#include "mlndt/cloud/io.h"

namespace mlndt {
namespace testing {
namespace {

PointCloud ReadScan(const std::string& folder, int64_t index) {
  const std::string name = std::to_string(index);
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(
      folder + "/pcd/" + std::string(6 - name.size(), '0') + name + ".pcd",
      &cloud,
      nullptr,
      &error))
      << error;
  return cloud;
}

}  // namespace

SharedPair ReadSharedPair(const std::string& folder, const std::string& key) {
  std::map<std::string, ReferencePair> references;
  std::string error;
  EXPECT_TRUE(
      ReadReferencePairs(folder + "/reference_pairs.json", &references, &error))
      << error;
  SharedPair shared;
  const auto it = references.find(key);
  EXPECT_NE(it, references.end()) << key << " is not in " << folder;
  if (it == references.end()) return shared;
  shared.pair = it->second;
  shared.reference = ReadScan(folder, shared.pair.reference_index);
  shared.input = ReadScan(folder, shared.pair.input_index);
  return shared;
}

}  // namespace testing
}  // namespace mlndt
