#pragma once

// Writing a simulated scan as PCD v0.7, DATA binary, little-endian:
//   FIELDS x y z time ring,  SIZE 4 4 4 4 2,  TYPE F F F F U
// x, y, z [m] in the sensor frame at the point's firing time; time [s]
// after the scan's stamp (its sweep's start); ring the laser. mlndt's
// reader takes x, y, z and skips the rest. The same scan gives the same
// bytes.

#include <string>

#include "lab/sim/scan_renderer.h"

namespace mlndt {
namespace sim {

// The file's bytes.
std::string SimScanPcd(const SimScan& scan);

// Written with WriteFileAtomically; false with *error.
bool WriteSimScanPcd(const std::string& path,
                     const SimScan& scan,
                     std::string* error);

}  // namespace sim
}  // namespace mlndt
