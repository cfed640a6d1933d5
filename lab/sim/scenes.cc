#include "lab/sim/scenes.h"

#include <glog/logging.h>

#include "lab/sim/corridor_scene.h"
#include "lab/sim/field_scene.h"
#include "lab/sim/rooms_scene.h"
#include "lab/sim/stairwell_scene.h"
#include "lab/sim/street_scene.h"
#include "lab/sim/tunnel_scene.h"
#include "lab/sim/vegetation_scene.h"

namespace mlndt {
namespace sim {
namespace {

// Builds with default options, which are valid (checked).
template <typename Options, typename Build>
Scene BuildDefault(Build build, uint64_t seed) {
  const Options options;
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  return build(options, seed);
}

}  // namespace

std::vector<std::string> SceneNames() {
  return {"street",
          "corridor",
          "tunnel",
          "rooms",
          "stairwell",
          "field",
          "vegetation"};
}

bool BuildScene(const std::string& name,
                uint64_t seed,
                Scene* scene,
                std::string* error) {
  CHECK(scene != nullptr);
  if (name == "street") {
    *scene = BuildDefault<StreetSceneOptions>(BuildStreetScene, seed);
  } else if (name == "corridor") {
    *scene = BuildDefault<CorridorSceneOptions>(BuildCorridorScene, seed);
  } else if (name == "tunnel") {
    *scene = BuildDefault<TunnelSceneOptions>(BuildTunnelScene, seed);
  } else if (name == "rooms") {
    *scene = BuildDefault<RoomsSceneOptions>(BuildRoomsScene, seed);
  } else if (name == "stairwell") {
    *scene = BuildDefault<StairwellSceneOptions>(BuildStairwellScene, seed);
  } else if (name == "field") {
    *scene = BuildDefault<FieldSceneOptions>(BuildFieldScene, seed);
  } else if (name == "vegetation") {
    *scene = BuildDefault<VegetationSceneOptions>(BuildVegetationScene, seed);
  } else {
    *error = "unknown scene '" + name +
             "' (street, corridor, tunnel, rooms, stairwell, field, "
             "vegetation)";
    return false;
  }
  return true;
}

bool IsIndoorScene(const std::string& name) {
  return name == "corridor" || name == "rooms" || name == "stairwell";
}

}  // namespace sim
}  // namespace mlndt
