#include "lab/eval/reference_pairs.h"

#include <glog/logging.h>

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

#include "mlndt/cloud/internal/cloud_readers.h"

namespace mlndt {
namespace {

using Json = nlohmann::json;

// How far R^T R may be from the identity (and det R from 1); the files
// print 6-9 significant digits. As ReadKittiPoses (pose_io.h).
constexpr double kRotationTolerance = 1e-3;
// How far a free direction's length may be from 1.
constexpr double kUnitTolerance = 1e-6;

bool ParseIndex(const std::string& text, int64_t* value) {
  if (text.empty() || text.front() == '-' || text.front() == '+') return false;
  const char* end = text.data() + text.size();
  const std::from_chars_result result =
      std::from_chars(text.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

bool ParseKey(const std::string& key, int64_t* i, int64_t* j) {
  const size_t underscore = key.find('_');
  return underscore != std::string::npos &&
         ParseIndex(key.substr(0, underscore), i) &&
         ParseIndex(key.substr(underscore + 1), j);
}

// Reads a 12-number row-major 3x4 matrix. False with *problem.
bool ReadMatrix(const Json& value,
                Isometry3d* transform,
                std::string* problem) {
  if (!value.is_array() || value.size() != 12) {
    *problem = "expected an array of 12 numbers (row-major 3x4), found " +
               (value.is_array() ? std::to_string(value.size()) + " elements"
                                 : std::string(value.type_name()));
    return false;
  }
  Eigen::Matrix<double, 3, 4> rows;
  for (int k = 0; k < 12; ++k) {
    const Json& number = value[static_cast<size_t>(k)];
    if (!number.is_number() || !std::isfinite(number.get<double>())) {
      *problem = "element " + std::to_string(k) + " is not a finite number";
      return false;
    }
    rows(k / 4, k % 4) = number.get<double>();
  }
  const Matrix3d rotation = rows.leftCols<3>();
  const double orthogonality =
      (rotation.transpose() * rotation - Matrix3d::Identity())
          .cwiseAbs()
          .maxCoeff();
  if (orthogonality > kRotationTolerance ||
      std::abs(rotation.determinant() - 1.0) > kRotationTolerance) {
    *problem = "the 3x3 part is not a rotation matrix";
    return false;
  }
  transform->setIdentity();
  transform->linear() = rotation;
  transform->translation() = rows.col(3);
  return true;
}

bool ReadSpread(const Json& value, double* spread, std::string* problem) {
  if (!value.is_number() || !std::isfinite(value.get<double>()) ||
      value.get<double>() < 0.0) {
    *problem = "expected a finite number >= 0";
    return false;
  }
  *spread = value.get<double>();
  return true;
}

// "free_directions": an array of unit 6-vectors. False with *problem.
bool ReadFreeDirections(const Json& value,
                        std::vector<Vector6d>* directions,
                        std::string* problem) {
  if (!value.is_array()) {
    *problem = "expected an array of 6-number arrays";
    return false;
  }
  for (size_t d = 0; d < value.size(); ++d) {
    const Json& direction = value[d];
    const std::string which = "direction " + std::to_string(d) + ": ";
    if (!direction.is_array() || direction.size() != 6) {
      *problem = which + "expected an array of 6 numbers";
      return false;
    }
    Vector6d v;
    for (int k = 0; k < 6; ++k) {
      const Json& number = direction[static_cast<size_t>(k)];
      if (!number.is_number() || !std::isfinite(number.get<double>())) {
        *problem =
            which + "element " + std::to_string(k) + " is not a finite number";
        return false;
      }
      v(k) = number.get<double>();
    }
    if (std::abs(v.norm() - 1.0) > kUnitTolerance) {
      *problem = which + "not of unit length";
      return false;
    }
    directions->push_back(v);
  }
  return true;
}

// One entry; false with *problem "<member>: <what>" (no path, no key).
bool ReadEntry(const Json& entry, ReferencePair* pair, std::string* problem) {
  if (!entry.is_object()) {
    *problem = "expected an object, found " + std::string(entry.type_name());
    return false;
  }
  if (entry.contains("source")) {
    if (!entry.at("source").is_string()) {
      *problem = "source: expected a string";
      return false;
    }
    pair->source = entry.at("source").get<std::string>();
  }
  const bool consensus = pair->source.empty();
  for (const char* member :
       {"reference_from_input", "spread_m", "spread_deg"}) {
    const bool optional = !consensus && member[0] == 's';
    if (!entry.contains(member) && !optional) {
      *problem = std::string(member) + ": missing";
      return false;
    }
  }
  std::string what;
  if (!ReadMatrix(entry.at("reference_from_input"),
                  &pair->reference_from_input,
                  &what)) {
    *problem = "reference_from_input: " + what;
    return false;
  }
  for (const auto& [member, spread] :
       {std::pair{"spread_m", &pair->spread_m},
        std::pair{"spread_deg", &pair->spread_deg}}) {
    if (!entry.contains(member)) continue;
    if (!ReadSpread(entry.at(member), spread, &what)) {
      *problem = std::string(member) + ": " + what;
      return false;
    }
  }
  if (entry.contains("prior_from_input")) {
    Isometry3d prior;
    if (!ReadMatrix(entry.at("prior_from_input"), &prior, &what)) {
      *problem = "prior_from_input: " + what;
      return false;
    }
    pair->prior_from_input = prior;
  }
  if (entry.contains("free_directions") &&
      !ReadFreeDirections(
          entry.at("free_directions"), &pair->free_directions, &what)) {
    *problem = "free_directions: " + what;
    return false;
  }
  return true;
}

}  // namespace

std::string ReferencePairKey(int64_t reference_index, int64_t input_index) {
  return std::to_string(reference_index) + "_" + std::to_string(input_index);
}

bool ReadReferencePairs(const std::string& path,
                        std::map<std::string, ReferencePair>* pairs,
                        std::string* error) {
  CHECK(pairs != nullptr);
  CHECK(error != nullptr);
  pairs->clear();
  std::string text;
  if (!internal::ReadFileToString(path, &text, error)) return false;
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::exception& e) {
    *error = path + ": malformed JSON: " + e.what();
    return false;
  }
  if (!root.is_object()) {
    *error = path + ": expected a JSON object of pairs keyed \"i_j\", found " +
             root.type_name();
    return false;
  }
  for (const auto& [key, entry] : root.items()) {
    ReferencePair pair;
    if (!ParseKey(key, &pair.reference_index, &pair.input_index)) {
      *error = path + ": key \"" + key +
               "\": expected \"i_j\" with non-negative integers i and j";
      pairs->clear();
      return false;
    }
    std::string problem;
    if (!ReadEntry(entry, &pair, &problem)) {
      *error = path + ": \"" + key + "\": " + problem;
      pairs->clear();
      return false;
    }
    pairs->emplace(key, pair);
  }
  if (pairs->empty()) {
    *error = path + ": no pairs";
    return false;
  }
  return true;
}

}  // namespace mlndt
