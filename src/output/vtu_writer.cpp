#include "output/vtu_writer.hpp"

#include <fmt/format.h>

#include <iterator>

#include "output/text_file.hpp"

namespace camouflet {

namespace {

constexpr int vtk_vertex = 1;
constexpr int vtk_quad = 9;
constexpr int vtk_hexahedron = 12;

using Buffer = std::string;

void open_array(Buffer& b, const char* type, const char* name, int components) {
  fmt::format_to(std::back_inserter(b),
                 "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">\n",
                 type, name, components);
}
void close_array(Buffer& b) {
  b += "\n        </DataArray>\n";
}

// A dim-component vector field padded to 3 components (ParaView's vectors).
void vector_array(Buffer& b, const char* name, std::span<const double> field, std::size_t n, int dim) {
  open_array(b, "Float64", name, 3);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double v = (k < dim && !field.empty())
                           ? field[i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)]
                           : 0.0;
      fmt::format_to(std::back_inserter(b), "{:.10g} ", v);
    }
    if (i % 4 == 3) b += '\n';
  }
  close_array(b);
}

template <class T>
void scalar_array(Buffer& b, const char* type, const char* name, std::span<const T> field, std::size_t n) {
  open_array(b, type, name, 1);
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (std::is_integral_v<T>)
      fmt::format_to(std::back_inserter(b), "{} ", field.empty() ? T{} : field[i]);
    else
      fmt::format_to(std::back_inserter(b), "{:.10g} ", field.empty() ? T{} : field[i]);
    if (i % 8 == 7) b += '\n';
  }
  close_array(b);
}

void tensor_array(Buffer& b, const char* name, std::span<const SymTensor> field, std::size_t n) {
  open_array(b, "Float64", name, 6);
  for (std::size_t i = 0; i < n; ++i) {
    const SymTensor s = field.empty() ? SymTensor{} : field[i];
    fmt::format_to(std::back_inserter(b), "{:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g}\n", s.xx, s.yy,
                   s.zz, s.xy, s.yz, s.zx);
  }
  close_array(b);
}

void header(Buffer& b, std::size_t points, std::size_t cells, double time) {
  b += "<?xml version=\"1.0\"?>\n";
  b += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt64\">\n";
  b += "  <UnstructuredGrid>\n";
  b += "    <FieldData>\n";
  fmt::format_to(
      std::back_inserter(b),
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{:.17g}"
      "</DataArray>\n",
      time);
  b += "    </FieldData>\n";
  fmt::format_to(std::back_inserter(b), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", points,
                 cells);
}

void footer(Buffer& b) {
  b += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

void cells(Buffer& b, std::span<const std::int64_t> connectivity, std::size_t n_cells, int npe, int type) {
  b += "      <Cells>\n";
  open_array(b, "Int64", "connectivity", 1);
  for (std::size_t i = 0; i < connectivity.size(); ++i) {
    fmt::format_to(std::back_inserter(b), "{} ", connectivity[i]);
    if (i % static_cast<std::size_t>(npe) == static_cast<std::size_t>(npe - 1)) b += '\n';
  }
  close_array(b);
  open_array(b, "Int64", "offsets", 1);
  for (std::size_t c = 0; c < n_cells; ++c) fmt::format_to(std::back_inserter(b), "{} ", (c + 1) * npe);
  close_array(b);
  open_array(b, "UInt8", "types", 1);
  for (std::size_t c = 0; c < n_cells; ++c) fmt::format_to(std::back_inserter(b), "{} ", type);
  close_array(b);
  b += "      </Cells>\n";
}

void points(Buffer& b, std::span<const double> position, std::size_t n, int dim) {
  b += "      <Points>\n";
  vector_array(b, "position", position, n, dim);
  b += "      </Points>\n";
}

}  // namespace

void write_mesh_vtu(const std::filesystem::path& path, const FieldSnapshot& s, std::span<const std::int64_t> node_id,
                    std::span<const std::int64_t> element_id) {
  const int dim = s.dimension;
  const std::size_t n = s.node_count(), m = s.element_count();
  Buffer b;
  b.reserve(200 * (n + m));
  header(b, n, m, s.time);
  b += "      <PointData Vectors=\"velocity\">\n";
  vector_array(b, "velocity", s.node_velocity, n, dim);
  vector_array(b, "displacement", s.node_displacement, n, dim);
  vector_array(b, "acceleration", s.node_acceleration, n, dim);
  if (!node_id.empty()) scalar_array(b, "Int64", "node_id", node_id, n);
  b += "      </PointData>\n";
  b += "      <CellData Scalars=\"pressure\" Tensors=\"stress\">\n";
  scalar_array(b, "Float64", "density", s.element_density, m);
  scalar_array(b, "Float64", "pressure", s.element_pressure, m);
  tensor_array(b, "stress", s.element_stress, m);
  scalar_array(b, "Float64", "plastic_strain", s.element_plastic_strain, m);
  scalar_array(b, "Float64", "temperature", s.element_temperature, m);
  scalar_array(b, "Float64", "damage", s.element_damage, m);
  scalar_array(b, "Int32", "material", s.element_material, m);
  if (!element_id.empty()) scalar_array(b, "Int64", "element_id", element_id, m);
  b += "      </CellData>\n";
  points(b, s.node_position, n, dim);
  cells(b, s.connectivity, m, s.nodes_per_element, dim == 3 ? vtk_hexahedron : vtk_quad);
  footer(b);
  write_file_atomically(path, b);
}

void write_mesh_pvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces) {
  // The arrays of write_mesh_vtu's pieces, declared once.
  Buffer b;
  b += "<?xml version=\"1.0\"?>\n";
  b += "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt64\">\n";
  b += "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  const auto array = [&b](const char* type, const char* name, int components) {
    fmt::format_to(std::back_inserter(b), "        <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n",
                   type, name, components);
  };
  b += "      <PPointData Vectors=\"velocity\">\n";
  for (const char* name : {"velocity", "displacement", "acceleration"}) array("Float64", name, 3);
  array("Int64", "node_id", 1);
  b += "      </PPointData>\n";
  b += "      <PCellData Scalars=\"pressure\" Tensors=\"stress\">\n";
  array("Float64", "density", 1);
  array("Float64", "pressure", 1);
  array("Float64", "stress", 6);
  for (const char* name : {"plastic_strain", "temperature", "damage"}) array("Float64", name, 1);
  array("Int32", "material", 1);
  array("Int64", "element_id", 1);
  b += "      </PCellData>\n";
  b += "      <PPoints>\n";
  array("Float64", "position", 3);
  b += "      </PPoints>\n";
  for (const std::string& piece : pieces) fmt::format_to(std::back_inserter(b), "    <Piece Source=\"{}\"/>\n", piece);
  b += "  </PUnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, b);
}

void write_particle_vtu(const std::filesystem::path& path, const FieldSnapshot& s) {
  const int dim = s.dimension;
  const std::size_t n = s.particle_count();
  Buffer b;
  b.reserve(300 * n + 1024);
  header(b, n, n, s.time);
  b += "      <PointData Scalars=\"pressure\" Vectors=\"velocity\" Tensors=\"stress\">\n";
  vector_array(b, "velocity", s.particle_velocity, n, dim);
  vector_array(b, "displacement", s.particle_displacement, n, dim);
  vector_array(b, "acceleration", s.particle_acceleration, n, dim);
  scalar_array(b, "Float64", "density", s.particle_density, n);
  scalar_array(b, "Float64", "pressure", s.particle_pressure, n);
  tensor_array(b, "stress", s.particle_stress, n);
  scalar_array(b, "Float64", "plastic_strain", s.particle_plastic_strain, n);
  scalar_array(b, "Float64", "temperature", s.particle_temperature, n);
  scalar_array(b, "Float64", "damage", s.particle_damage, n);
  scalar_array(b, "Int32", "material", s.particle_material, n);
  scalar_array(b, "Float64", "smoothing_length", s.particle_smoothing_length, n);
  scalar_array(b, "Int32", "neighbour_count", s.particle_neighbour_count, n);
  b += "      </PointData>\n";
  points(b, s.particle_position, n, dim);
  std::vector<std::int64_t> vertices(n);
  for (std::size_t i = 0; i < n; ++i) vertices[i] = static_cast<std::int64_t>(i);
  cells(b, vertices, n, 1, vtk_vertex);
  footer(b);
  write_file_atomically(path, b);
}

void PvdIndex::add(double time, int part, const std::string& file) {
  entries_.push_back({time, part, file});
}

void PvdIndex::write(const std::filesystem::path& path) const {
  std::string b = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& e : entries_)
    fmt::format_to(std::back_inserter(b), "    <DataSet timestep=\"{:.17g}\" part=\"{}\" file=\"{}\"/>\n",
                   e.time, e.part, e.file);
  b += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(path, b);
}

}  // namespace camouflet
