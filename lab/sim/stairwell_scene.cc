#include "lab/sim/stairwell_scene.h"

#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

constexpr double kSlab = 0.2;  // Thickness under steps and landings [m].

struct Stairs {
  double storey = 3.0;   // Height per storey [m].
  int steps = 9;         // Per flight.
  double rise = 0.17;    // Per step [m].
  double run = 0.28;     // Per step [m].
  double width = 1.2;    // Of a flight [m].
  double gap = 0.2;      // Between the two flights [m].
  double landing = 1.4;  // Depth of a landing along x [m].

  double flight_length() const { return steps * run; }
  double shaft_length() const { return 2.0 * landing + flight_length(); }
  double shaft_width() const { return 2.0 * width + gap; }
};

// One flight from (x_start, z_start), `direction` +1 (+x) or -1, its
// y range [y0, y1], a balustrade at y = rail_y.
void AddFlight(const Stairs& s,
               double x_start,
               double z_start,
               double direction,
               double y0,
               double y1,
               double rail_y,
               TriangleMesh* mesh) {
  for (int k = 0; k < s.steps; ++k) {
    const double xa = x_start + direction * k * s.run;
    const double xb = xa + direction * s.run;
    const double top = z_start + (k + 1) * s.rise;
    AddBox(Vector3d(std::min(xa, xb), y0, top - s.rise - kSlab),
           Vector3d(std::max(xa, xb), y1, top),
           mesh);
  }
  const double x_end = x_start + direction * s.flight_length();
  const double z_end = z_start + s.steps * s.rise;
  mesh->AddQuad(Vector3d(x_start, rail_y, z_start + 0.1),
                Vector3d(x_end, rail_y, z_end + 0.1),
                Vector3d(x_end, rail_y, z_end + 1.0),
                Vector3d(x_start, rail_y, z_start + 1.0));
}

void AddShaft(const Stairs& s, int storeys, TriangleMesh* mesh) {
  const double L = s.shaft_length();
  const double W = s.shaft_width();
  const double top = storeys * s.storey + 3.0;
  const double t = 0.2;
  AddBox(Vector3d(-t, -t, -kSlab), Vector3d(0, W + t, top), mesh);
  AddBox(Vector3d(L, -t, -kSlab), Vector3d(L + t, W + t, top), mesh);
  AddBox(Vector3d(0, -t, -kSlab), Vector3d(L, 0, top), mesh);
  AddBox(Vector3d(0, W, -kSlab), Vector3d(L, W + t, top), mesh);
  AddBox(Vector3d(0, 0, top), Vector3d(L, W, top + t), mesh);
}

}  // namespace

bool StairwellSceneOptions::IsValid(std::string* error) const {
  if (!(storeys >= 1 && storeys <= 50 && min_storey_height_m >= 2.2 &&
        max_storey_height_m >= min_storey_height_m &&
        min_flight_width_m >= 0.8 &&
        max_flight_width_m >= min_flight_width_m)) {
    *error =
        "stairwell: need 1 <= storeys <= 50, storey height >= 2.2, flight "
        "width >= 0.8, each max >= its min";
    return false;
  }
  return true;
}

Scene BuildStairwellScene(const StairwellSceneOptions& options, uint64_t seed) {
  SimRandom random(seed, "stairwell");
  Scene scene;
  scene.kind = "stairwell";
  scene.seed = seed;
  Stairs s;
  s.storey =
      random.Uniform(options.min_storey_height_m, options.max_storey_height_m);
  s.steps = static_cast<int>(std::lround(0.5 * s.storey / 0.17));
  s.rise = 0.5 * s.storey / s.steps;
  s.run = random.Uniform(0.26, 0.31);
  s.width =
      random.Uniform(options.min_flight_width_m, options.max_flight_width_m);
  s.gap = random.Uniform(0.1, 0.4);
  s.landing = random.Uniform(1.2, 1.8);
  const double L = s.shaft_length();
  const double W = s.shaft_width();
  const double far = s.landing + s.flight_length();
  AddShaft(s, options.storeys, &scene.mesh);
  const double y_a = 0.5 * s.width;      // Centre of the +x flights.
  const double y_b = W - 0.5 * s.width;  // Centre of the -x flights.
  for (int f = 0; f < options.storeys; ++f) {
    const double z = f * s.storey;
    const double half = z + 0.5 * s.storey;
    AddBox(Vector3d(0, 0, z - kSlab), Vector3d(s.landing, W, z), &scene.mesh);
    AddBox(Vector3d(far, 0, half - kSlab), Vector3d(L, W, half), &scene.mesh);
    AddFlight(s, s.landing, z, 1.0, 0, s.width, s.width, &scene.mesh);
    AddFlight(s, far, half, -1.0, W - s.width, W, W - s.width, &scene.mesh);
    // A door in the wall at x = 0, recessed 0.1 m.
    AddBox(Vector3d(-0.1, 0.2 * W, z),
           Vector3d(0.0, 0.2 * W + 0.9, z + 2.0),
           &scene.mesh);
    scene.path.points.push_back(Vector3d(0.5 * s.landing, y_a, z));
    scene.path.points.push_back(Vector3d(s.landing, y_a, z));
    scene.path.points.push_back(Vector3d(far, y_a, half));
    scene.path.points.push_back(Vector3d(0.5 * (far + L), y_a, half));
    scene.path.points.push_back(Vector3d(0.5 * (far + L), y_b, half));
    scene.path.points.push_back(Vector3d(far, y_b, half));
    scene.path.points.push_back(Vector3d(s.landing, y_b, z + s.storey));
    scene.path.points.push_back(Vector3d(0.5 * s.landing, y_b, z + s.storey));
  }
  AddBox(Vector3d(0, 0, options.storeys * s.storey - kSlab),
         Vector3d(s.landing, W, options.storeys * s.storey),
         &scene.mesh);
  scene.path.lateral_half_width_m = 0.15;
  scene.parameters = {{"storey_height_m", s.storey},
                      {"steps", s.steps},
                      {"run_m", s.run},
                      {"flight_width_m", s.width},
                      {"gap_m", s.gap},
                      {"landing_m", s.landing},
                      {"storeys", options.storeys}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
