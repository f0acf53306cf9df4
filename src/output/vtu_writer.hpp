#pragma once
// Field snapshots for ParaView: VTK XML UnstructuredGrid files (ASCII data, ten
// significant digits) and the .pvd collection that indexes them by time; on MPI
// ranks a piece per rank (appended raw binary data, exact) and a .pvtu per
// snapshot that joins them (docs/parallel.md).
//   mesh:      quads (VTK_QUAD) or hexes (VTK_HEXAHEDRON); point data velocity,
//              displacement, acceleration; cell data density, pressure,
//              stress (xx yy zz xy yz zx, ParaView's symmetric-tensor order),
//              plastic_strain, damage, material.
//   particles: one VTK_VERTEX cell per particle, the same quantities as point
//              data, plus smoothing_length and neighbour_count.
// 2-D coordinates are written with z = 0 (axisymmetric: x = r, y = z).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "model/snapshot.hpp"

namespace camouflet {

// With `node_id` and `element_id` (a piece of a run across MPI ranks: 1-based ids in the whole
// mesh, one per node and element of the piece) they are written as point and cell data too, and
// the data is appended raw binary (little-endian, UInt64 byte counts).
void write_mesh_vtu(const std::filesystem::path& path, const FieldSnapshot& state,
                    std::span<const std::int64_t> node_id = {}, std::span<const std::int64_t> element_id = {});
// The .pvtu that joins the pieces of one snapshot of a run across ranks (each a file written by
// write_mesh_vtu with ids), `pieces` relative to the .pvtu's folder.
void write_mesh_pvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces);
void write_particle_vtu(const std::filesystem::path& path, const FieldSnapshot& state);

// The .pvd index: one DataSet line per file; part 0 = mesh, 1 = particles.
class PvdIndex {
 public:
  void add(double time, int part, const std::string& file);
  // Rewrites the whole index (atomically) so it always lists complete files.
  void write(const std::filesystem::path& path) const;

 private:
  struct Entry {
    double time;
    int part;
    std::string file;
  };
  std::vector<Entry> entries_;
};

}  // namespace camouflet
