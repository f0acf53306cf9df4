#include "parallel/whole_snapshot.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace camouflet {

namespace {

// A rank's record: its owned nodes (global id, then position, displacement, velocity and
// acceleration, D each), then its elements (global id, density, pressure, six stresses, plastic
// strain, damage, temperature, material), all as doubles (ids and materials are exact in them).
constexpr int element_record = 13;

// `nodes`: the local nodes to send (owned ones), `elements`: the local elements.
std::vector<double> pack(const RankPart& part, const FieldSnapshot& s, std::span<const std::size_t> nodes,
                         std::span<const std::size_t> elements) {
  const LocalMesh& local = part.local();
  const auto d = static_cast<std::size_t>(s.dimension);
  std::vector<double> out;
  out.reserve(2 + nodes.size() * (1 + 4 * d) + elements.size() * element_record);
  out.push_back(static_cast<double>(nodes.size()));
  for (const std::size_t n : nodes) {
    out.push_back(static_cast<double>(local.global_node[n]));
    for (const auto* field : {&s.node_position, &s.node_displacement, &s.node_velocity, &s.node_acceleration})
      for (std::size_t i = 0; i < d; ++i) out.push_back((*field)[n * d + i]);
  }
  out.push_back(static_cast<double>(elements.size()));
  for (const std::size_t e : elements) {
    const SymTensor& t = s.element_stress[e];
    for (double v : {static_cast<double>(local.global_element[e]), s.element_density[e], s.element_pressure[e], t.xx,
                     t.yy, t.zz, t.xy, t.yz, t.zx, s.element_plastic_strain[e], s.element_damage[e],
                     s.element_temperature[e]})
      out.push_back(v);
    out.push_back(static_cast<double>(s.element_material[e]));
  }
  return out;
}

}  // namespace

void WholeSnapshot::restrict_to(const RankPart& part, std::span<const std::int64_t> nodes,
                                std::span<const std::int64_t> elements) {
  const LocalMesh& local = part.local();
  const auto wanted = [](std::span<const std::int64_t> list, std::int64_t id) {
    return std::binary_search(list.begin(), list.end(), id);
  };
  if (!std::is_sorted(nodes.begin(), nodes.end()) || !std::is_sorted(elements.begin(), elements.end()))
    throw std::logic_error("WholeSnapshot::restrict_to: ids must be ascending");
  nodes_.clear();
  elements_.clear();
  for (std::size_t n = 0; n < local.global_node.size(); ++n)
    if (local.owned[n] && wanted(nodes, local.global_node[n])) nodes_.push_back(n);
  for (std::size_t e = 0; e < local.global_element.size(); ++e)
    if (wanted(elements, local.global_element[e])) elements_.push_back(e);
  restricted_ = true;
  blanked_ = false;
}

const FieldSnapshot& WholeSnapshot::gather(const RankPart& part, const FieldSnapshot& mine) {
  if (mine.particle_count() > 0) throw std::logic_error("WholeSnapshot: particles do not cross ranks yet");
  const Communicator& comm = part.comm();
  if (!restricted_) {  // everything this rank steps: its owned nodes, its elements
    nodes_.clear();
    elements_.clear();
    for (std::size_t n = 0; n < part.local().owned.size(); ++n)
      if (part.local().owned[n]) nodes_.push_back(n);
    for (std::size_t e = 0; e < part.local().global_element.size(); ++e) elements_.push_back(e);
  }
  const std::vector<double> record = pack(part, mine, nodes_, elements_);
  const std::int64_t size = static_cast<std::int64_t>(record.size());
  const std::vector<std::int64_t> sizes = comm.all_gather(std::span<const std::int64_t>(&size, 1));
  std::vector<int> ranks;
  std::vector<std::vector<double>> sends, receives;
  if (comm.rank() == 0) {
    for (int r = 1; r < comm.size(); ++r) {
      ranks.push_back(r);
      sends.emplace_back();
      receives.emplace_back(static_cast<std::size_t>(sizes[static_cast<std::size_t>(r)]));
    }
  } else {
    ranks.push_back(0);
    sends.push_back(record);
    receives.emplace_back();
  }
  comm.exchange(ranks, sends, receives);
  view_ = FieldSnapshot{};
  if (comm.rank() != 0) return view_;

  const FemMesh& mesh = whole_->mesh;
  const auto d = static_cast<std::size_t>(mesh.dimension);
  const std::size_t nn = mesh.node_count(), ne = mesh.element_count();
  // Whole: every entry is sent. Restricted: the rest blanked once, the same entries sent each time.
  if (!restricted_ || !blanked_) {
    const double fill = restricted_ ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    for (auto* field : {&position_, &displacement_, &velocity_, &acceleration_}) field->assign(nn * d, fill);
    for (auto* field : {&density_, &pressure_, &plastic_strain_, &damage_, &temperature_}) field->assign(ne, fill);
    stress_.assign(ne, SymTensor{fill, fill, fill, fill, fill, fill});
    material_.assign(ne, restricted_ ? -1 : 0);
    blanked_ = restricted_;
  }
  const auto unpack = [&](const std::vector<double>& in) {
    std::size_t at = 0;
    const auto nodes = static_cast<std::size_t>(in[at++]);
    for (std::size_t k = 0; k < nodes; ++k) {
      const auto g = static_cast<std::size_t>(in[at++]);
      for (auto* field : {&position_, &displacement_, &velocity_, &acceleration_})
        for (std::size_t i = 0; i < d; ++i) (*field)[g * d + i] = in[at++];
    }
    const auto elements = static_cast<std::size_t>(in[at++]);
    for (std::size_t k = 0; k < elements; ++k) {
      const auto g = static_cast<std::size_t>(in[at++]);
      density_[g] = in[at++];
      pressure_[g] = in[at++];
      SymTensor& t = stress_[g];
      t.xx = in[at++], t.yy = in[at++], t.zz = in[at++], t.xy = in[at++], t.yz = in[at++], t.zx = in[at++];
      plastic_strain_[g] = in[at++];
      damage_[g] = in[at++];
      temperature_[g] = in[at++];
      material_[g] = static_cast<int>(in[at++]);
    }
  };
  unpack(record);
  for (const auto& r : receives) unpack(r);

  view_.dimension = mine.dimension;
  view_.mode = mine.mode;
  view_.time = mine.time;
  view_.cycle = mine.cycle;
  view_.node_position = position_;
  view_.node_displacement = displacement_;
  view_.node_velocity = velocity_;
  view_.node_acceleration = acceleration_;
  view_.nodes_per_element = mesh.nodes_per_element;
  view_.connectivity = mesh.connectivity;
  view_.element_density = density_;
  view_.element_pressure = pressure_;
  view_.element_stress = stress_;
  view_.element_plastic_strain = plastic_strain_;
  view_.element_damage = damage_;
  view_.element_temperature = temperature_;
  view_.element_material = material_;
  return view_;
}

}  // namespace camouflet
