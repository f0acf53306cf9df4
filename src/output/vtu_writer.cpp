#include "output/vtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <iterator>
#include <type_traits>

#include "output/text_file.hpp"

namespace camouflet {

namespace {

constexpr int vtk_vertex = 1;
constexpr int vtk_quad = 9;
constexpr int vtk_hexahedron = 12;

// A file being built: the XML, and with appended data the raw bytes that follow it.
struct Buffer {
  explicit Buffer(bool appended_data = false) : appended(appended_data) {}
  std::string xml;
  bool appended;
  std::string data;  // appended: per array its byte count (UInt64) then its values, little-endian
  Buffer& operator+=(const char* text) {
    xml += text;
    return *this;
  }
  Buffer& operator+=(char c) {
    xml += c;
    return *this;
  }
};

static_assert(std::endian::native == std::endian::little,
              "appended VTU data is written as the host stores it");

// VTK's name of the type each array is written in.
template <class T>
constexpr const char* vtk_type() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::int64_t> ||
                std::is_same_v<T, std::int32_t> || std::is_same_v<T, std::uint8_t>);
  return "UInt8";
}

// One data array of `components` values per tuple. ASCII: ten significant digits, a line break
// after every `per_line` values (none when 0). Appended: the raw bytes, located by their offset.
template <class T>
void put_array(Buffer& b, const char* name, int components, std::span<const T> values, std::size_t per_line) {
  if (b.appended) {
    fmt::format_to(std::back_inserter(b.xml),
                   "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                   "format=\"appended\" offset=\"{}\"/>\n",
                   vtk_type<T>(), name, components, b.data.size());
    const std::uint64_t bytes = values.size() * sizeof(T);
    b.data.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
    b.data.append(reinterpret_cast<const char*>(values.data()), bytes);
    return;
  }
  fmt::format_to(std::back_inserter(b.xml),
                 "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">\n",
                 vtk_type<T>(), name, components);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if constexpr (std::is_integral_v<T>)
      fmt::format_to(std::back_inserter(b.xml), "{} ", static_cast<std::int64_t>(values[i]));
    else
      fmt::format_to(std::back_inserter(b.xml), "{:.10g} ", values[i]);
    if (per_line > 0 && i % per_line == per_line - 1) b.xml += '\n';
  }
  b.xml += "\n        </DataArray>\n";
}

// A dim-component vector field padded to 3 components (ParaView's vectors).
void vector_array(Buffer& b, const char* name, std::span<const double> field, std::size_t n, int dim) {
  std::vector<double> v(3 * n, 0.0);
  if (!field.empty())
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < dim; ++k)
        v[3 * i + static_cast<std::size_t>(k)] =
            field[i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)];
  put_array<double>(b, name, 3, v, 12);
}

template <class T, class Stored = T>
void scalar_array(Buffer& b, const char* name, std::span<const T> field, std::size_t n) {
  std::vector<Stored> v(n, Stored{});
  if (!field.empty())
    for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<Stored>(field[i]);
  put_array<Stored>(b, name, 1, v, 8);
}

void tensor_array(Buffer& b, const char* name, std::span<const SymTensor> field, std::size_t n) {
  std::vector<double> v(6 * n, 0.0);
  if (!field.empty())
    for (std::size_t i = 0; i < n; ++i) {
      const SymTensor& s = field[i];
      const double t[6] = {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx};
      std::copy(t, t + 6, v.begin() + static_cast<std::ptrdiff_t>(6 * i));
    }
  put_array<double>(b, name, 6, v, 6);
}

void header(Buffer& b, std::size_t points, std::size_t cells, double time) {
  b += "<?xml version=\"1.0\"?>\n";
  b += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt64\">\n";
  b += "  <UnstructuredGrid>\n";
  b += "    <FieldData>\n";
  fmt::format_to(
      std::back_inserter(b.xml),
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{:.17g}"
      "</DataArray>\n",
      time);
  b += "    </FieldData>\n";
  fmt::format_to(std::back_inserter(b.xml), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 points, cells);
}

void footer(Buffer& b) {
  b += "    </Piece>\n  </UnstructuredGrid>\n";
  if (b.appended) {
    b += "  <AppendedData encoding=\"raw\">\n   _";
    b.xml += b.data;
    b += "\n  </AppendedData>\n";
  }
  b += "</VTKFile>\n";
}

void cells(Buffer& b, std::span<const std::int64_t> connectivity, std::size_t n_cells, int npe, int type) {
  b += "      <Cells>\n";
  put_array<std::int64_t>(b, "connectivity", 1, connectivity, static_cast<std::size_t>(npe));
  std::vector<std::int64_t> offsets(n_cells);
  for (std::size_t c = 0; c < n_cells; ++c)
    offsets[c] = static_cast<std::int64_t>((c + 1) * static_cast<std::size_t>(npe));
  put_array<std::int64_t>(b, "offsets", 1, offsets, 0);
  const std::vector<std::uint8_t> types(n_cells, static_cast<std::uint8_t>(type));
  put_array<std::uint8_t>(b, "types", 1, types, 0);
  b += "      </Cells>\n";
}

void points(Buffer& b, std::span<const double> position, std::size_t n, int dim) {
  b += "      <Points>\n";
  vector_array(b, "position", position, n, dim);
  b += "      </Points>\n";
}

}  // namespace

void write_mesh_vtu(const std::filesystem::path& path, const FieldSnapshot& s,
                    std::span<const std::int64_t> node_id, std::span<const std::int64_t> element_id) {
  const int dim = s.dimension;
  const std::size_t n = s.node_count(), m = s.element_count();
  // A piece of a run across ranks (with ids) in appended raw binary: exact values, 8 bytes each
  // against about 13 for ten ASCII digits, and no formatting; a serial snapshot in ASCII, which
  // scripts/run_metrics.py reads.
  Buffer b(!node_id.empty());
  (b.appended ? b.data : b.xml).reserve(200 * (n + m));
  header(b, n, m, s.time);
  b += "      <PointData Vectors=\"velocity\">\n";
  vector_array(b, "velocity", s.node_velocity, n, dim);
  vector_array(b, "displacement", s.node_displacement, n, dim);
  vector_array(b, "acceleration", s.node_acceleration, n, dim);
  if (!node_id.empty()) scalar_array<std::int64_t>(b, "node_id", node_id, n);
  b += "      </PointData>\n";
  b += "      <CellData Scalars=\"pressure\" Tensors=\"stress\">\n";
  scalar_array<double>(b, "density", s.element_density, m);
  scalar_array<double>(b, "pressure", s.element_pressure, m);
  tensor_array(b, "stress", s.element_stress, m);
  scalar_array<double>(b, "plastic_strain", s.element_plastic_strain, m);
  scalar_array<double>(b, "temperature", s.element_temperature, m);
  scalar_array<double>(b, "damage", s.element_damage, m);
  scalar_array<int, std::int32_t>(b, "material", s.element_material, m);
  if (!element_id.empty()) scalar_array<std::int64_t>(b, "element_id", element_id, m);
  b += "      </CellData>\n";
  points(b, s.node_position, n, dim);
  cells(b, s.connectivity, m, s.nodes_per_element, dim == 3 ? vtk_hexahedron : vtk_quad);
  footer(b);
  write_file_atomically(path, b.xml);
}

void write_mesh_pvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces) {
  // The arrays of write_mesh_vtu's pieces, declared once.
  std::string b;
  b += "<?xml version=\"1.0\"?>\n";
  b += "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt64\">\n";
  b += "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  const auto array = [&b](const char* type, const char* name, int components) {
    fmt::format_to(std::back_inserter(b),
                   "        <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n", type, name,
                   components);
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
  for (const std::string& piece : pieces)
    fmt::format_to(std::back_inserter(b), "    <Piece Source=\"{}\"/>\n", piece);
  b += "  </PUnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, b);
}

void write_particle_vtu(const std::filesystem::path& path, const FieldSnapshot& s) {
  const int dim = s.dimension;
  const std::size_t n = s.particle_count();
  Buffer b;
  b.xml.reserve(300 * n + 1024);
  header(b, n, n, s.time);
  b += "      <PointData Scalars=\"pressure\" Vectors=\"velocity\" Tensors=\"stress\">\n";
  vector_array(b, "velocity", s.particle_velocity, n, dim);
  vector_array(b, "displacement", s.particle_displacement, n, dim);
  vector_array(b, "acceleration", s.particle_acceleration, n, dim);
  scalar_array<double>(b, "density", s.particle_density, n);
  scalar_array<double>(b, "pressure", s.particle_pressure, n);
  tensor_array(b, "stress", s.particle_stress, n);
  scalar_array<double>(b, "plastic_strain", s.particle_plastic_strain, n);
  scalar_array<double>(b, "temperature", s.particle_temperature, n);
  scalar_array<double>(b, "damage", s.particle_damage, n);
  scalar_array<int, std::int32_t>(b, "material", s.particle_material, n);
  scalar_array<double>(b, "smoothing_length", s.particle_smoothing_length, n);
  scalar_array<int, std::int32_t>(b, "neighbour_count", s.particle_neighbour_count, n);
  b += "      </PointData>\n";
  points(b, s.particle_position, n, dim);
  std::vector<std::int64_t> vertices(n);
  for (std::size_t i = 0; i < n; ++i) vertices[i] = static_cast<std::int64_t>(i);
  cells(b, vertices, n, 1, vtk_vertex);
  footer(b);
  write_file_atomically(path, b.xml);
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
