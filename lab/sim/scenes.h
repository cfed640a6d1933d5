#pragma once

// The procedural scenes by name, each built from a seed with its default
// options:
//   street      buildings, cars, poles, trees along a straight street
//   corridor    a long featureless corridor (free along its axis)
//   tunnel      a long road tunnel (free along its axis)
//   rooms       a row of furnished rooms joined by doors
//   stairwell   switch-back stairs in a closed shaft
//   field       rolling open ground with few objects
//   vegetation  a wood of leafy trees and bushes

#include <cstdint>
#include <string>
#include <vector>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

std::vector<std::string> SceneNames();

// False with *error for an unknown name.
bool BuildScene(const std::string& name,
                uint64_t seed,
                Scene* scene,
                std::string* error);

// Whether the scene is indoors (hand-held is its natural trajectory).
bool IsIndoorScene(const std::string& name);

}  // namespace sim
}  // namespace mlndt
