#pragma once

// Compact, versioned binary storage of a layered NDT map (the paper's storage
// argument: a map is a few thousand cells, far smaller than the scan).
//
// Byte order: every field is LITTLE-ENDIAN, written and read byte by byte
// whatever the host's byte order (no struct or host-order memcpy); doubles
// are IEEE 754 binary64 with their 8 bytes in little-endian order. On
// little-endian hosts (x86-64, arm64) this is exactly the byte layout the
// first version-1 writer produced by copying host values, so every version-1
// file written before stays readable and the version is still 1.
//
// Layout (offsets in bytes):
//   header, 96 bytes (version 1) or 120 (version 2):
//     0   char[8]  "MLNDTMAP"
//     8   uint32   version: 2 when the map has cell rules (line_ratio or
//                  plane_ratio not 0, ndt_cell.h), else 1
//     12  int32    q (division constant)
//     16  int32    n (layers, 1..16)
//     20  int32    min points per cell
//     24  double   regularisation: min eigenvalue ratio
//     32  double   regularisation: min eigenvalue [m^2]
//     version 2 only, shifting what follows by 24 bytes:
//     40  double   line_ratio | 48 double plane_ratio |
//     56  double   in_plane_variance_scale
//     40  double   bounds min x, y, z [m]
//     64  double   bounds max x, y, z [m]
//     88  uint64   points the map was built from
//   then per layer, coarse to fine, 52 bytes of header:
//     double origin x, y, z [m] | double cell size [m] |
//     int32 dims x, y, z | uint64 number of cells
//   followed by 84 bytes per cell:
//     int64 linear key | int32 point count | double mean x, y, z [m] |
//     double covariance xx, xy, xz, yy, yz, zz [m^2]
//   last: uint64 FNV-1a (64-bit) checksum of every byte before it.
// W and C^-1 are recomputed on load (the covariance is regularised again,
// which reproduces it to ~1e-16; the cell rules decide on the regularised
// eigenvalues, so they keep the same cells). A version-1 file scores every
// cell with its whole covariance, as the builds that wrote it did.
//
// LoadLayeredGrid trusts nothing in the file, even with a valid checksum
// (anyone can compute one). Before allocating anything sized by a count it
// checks:
//   - n in 1..16 and the options valid (LayeredGridOptions::IsValid); the
//     bounding box finite and not inverted; n layer headers fit in the file;
//   - per layer: origin finite, cell size finite and > 0 and smaller than
//     the coarser layer's; dims in 1..10^6 per axis and consistent with the
//     box (origin at its min corner, the grid covering it with at most one
//     spare cell per axis, as LayeredGrid::Build makes it); the number of
//     cells at most the grid's dims product and at most what the bytes left
//     can hold (84 bytes a cell);
//   - the dense cell indexes the layers will build (4 bytes per grid cell
//     for layers of at most CellIndex::kMaxDenseCells grid cells) take at
//     most 3 * 64 MiB together; Build's layers grow by a factor q >= 2, so
//     its maps need at most 2 * 64 MiB;
//   - per cell: key inside the grid and unique, count >= 1, the counts of a
//     layer at most the map's number of points, the mean inside the cell
//     (to 1/1000 of its edge), a usable covariance.
// So a crafted file allocates at most its own size a few times over (cells,
// keys) plus the bounded dense indexes, and fails with an error naming the
// file, the layer and the problem.

#include <string>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {

// Writes with WriteFileAtomically (mlndt/common/atomic_file.h: temporary
// file, fsync, rename; the previous file survives any failure, a full disk
// included). Returns false with *error naming the path and the OS reason.
bool SaveLayeredGrid(const std::string& path,
                     const LayeredGrid& grid,
                     std::string* error);

// Reads a map written by SaveLayeredGrid. A missing, truncated, corrupt,
// foreign or inconsistent file returns false with *error naming the file and
// the problem, and leaves *grid unchanged.
bool LoadLayeredGrid(const std::string& path,
                     LayeredGrid* grid,
                     std::string* error);

}  // namespace mlndt
