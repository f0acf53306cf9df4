// Set-up, bookkeeping and reporting of the SPH package; the particle sums are
// in sph_forces.cpp, sph_motion.cpp and sph_kinematics.cpp.
#include "sph/sph_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "model/geostatic_stress.hpp"

namespace camouflet::sph {

template <int D>
double SphSystem<D>::geometric_weight(const Vec<D>& x) const {
  if (mode_ == GeometryMode::axisymmetric) return 2.0 * std::numbers::pi * std::abs(x[0]);
  return 1.0;
}

template <int D>
SphSystem<D>::SphSystem(const Model& model, const SphOptions& options, std::vector<MirrorPlane> planes)
    : mode_(model.run.mode), options_(options), planes_(std::move(planes)) {
  if (dimension_of(mode_) != D) throw std::invalid_argument("SphSystem: model dimension does not match");
  if (model.particles.coordinates.size() != D * model.particles.count())
    throw std::invalid_argument("SphSystem: particle coordinates do not match the dimension");
  kernel_.kind = options_.kernel;
  // Artificial stress weight f^n, f = W(r, h_ij) / W(dp, h_ij) with dp = h_ij / smoothing_factor:
  // the normalisation cancels, f = w(r / h_ij) / w(1 / smoothing_factor).
  tensile_shape_inverse_ = 1.0 / kernel_.shape(1.0 / options_.smoothing_factor);
  const double power = options_.artificial_stress_power;
  if (power >= 1.0 && power <= 8.0 && power == std::floor(power))
    tensile_power_integer_ = static_cast<int>(power);

  const auto& src = model.particles;
  const std::size_t n = src.count();
  p_.real = n;
  p_.position.resize(n);
  p_.velocity.resize(n);
  p_.mass.resize(n);
  p_.planar_density.resize(n);
  p_.smoothing_length.resize(n);
  p_.stress_term.resize(n);
  p_.tensile_term.resize(n);
  p_.wave_speed.resize(n);
  p_.stable_wave_speed.resize(n);
  p_.viscosity_alpha.assign(
      n, options_.viscosity_switch ? options_.viscosity_alpha_min : options_.viscosity_alpha);
  p_.correction.assign(n, SymTensor::identity());
  p_.acceleration.assign(n, Vec<D>{});
  p_.displacement.assign(n, Vec<D>{});
  p_.density.resize(n);
  p_.reference_smoothing_length.resize(n);
  p_.reference_planar_density.resize(n);
  p_.spacing.resize(n);
  p_.stress.resize(n);
  p_.pressure.resize(n);
  p_.plastic_strain.resize(n);
  p_.damage.resize(n);
  p_.temperature.resize(n);
  p_.material.resize(n);
  p_.part.resize(n);
  p_.slot.resize(n);
  p_.heating.assign(n, 0.0);
  p_.compression_rate.assign(n, 0.0);
  p_.neighbour_count.assign(n, 0);
  p_.strain_rate.resize(n);
  p_.spin.resize(n);
  p_.id.resize(n);
  for (std::size_t i = 0; i < n; ++i) p_.id[i] = static_cast<std::uint32_t>(i);

  materials_.resize(model.materials.size());
  batches_.resize(model.materials.size());
  batch_particles_.resize(model.materials.size());
  for (std::size_t m = 0; m < model.materials.size(); ++m) materials_[m] = model.materials[m].material;
  eos_family_.resize(materials_.size());
  for (std::size_t m = 0; m < materials_.size(); ++m) {
    eos_family_[m] = static_cast<int>(m);
    for (std::size_t k = 0; k < m && materials_[m]; ++k)
      if (materials_[k] && materials_[k]->eos().type() == materials_[m]->eos().type()) {
        eos_family_[m] = static_cast<int>(k);
        break;
      }
  }

  for (std::size_t i = 0; i < n; ++i) {
    const int part = src.particle_part[i];
    if (part < 0 || static_cast<std::size_t>(part) >= model.parts.size())
      throw std::invalid_argument(
          fmt::format("particle {} refers to part {} that does not exist", i + 1, part));
    const int mat = model.parts[part].material;
    if (mat < 0 || static_cast<std::size_t>(mat) >= model.materials.size() || !materials_[mat])
      throw InputError(model.parts[part].where, "part '" + model.parts[part].name + "' has no material");
    p_.part[i] = part;
    p_.material[i] = mat;
    p_.slot[i] = static_cast<std::uint32_t>(batch_particles_[mat].size());
    batch_particles_[mat].push_back(static_cast<std::uint32_t>(i));
    for (int d = 0; d < D; ++d) {
      p_.position[i][d] = src.coordinates[D * i + d];
      p_.velocity[i][d] = model.parts[part].initial_velocity[d];
    }
  }

  for (std::size_t m = 0; m < materials_.size(); ++m) {
    if (batch_particles_[m].empty()) continue;
    materials_[m]->setup(batches_[m], batch_particles_[m].size());
    std::vector<std::array<double, 3>> where(batch_particles_[m].size());
    for (std::size_t k = 0; k < where.size(); ++k)
      for (int d = 0; d < D; ++d) where[k][d] = p_.position[batch_particles_[m][k]][d];
    materials_[m]->eos().place(batches_[m], where, model.detonations);
  }
  set_geostatic_state(model);  // before the masses: they follow from the density that carries the overburden

  double h_min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& pts = batches_[p_.material[i]];
    const double rho = pts.density[p_.slot[i]];
    p_.density[i] = rho;
    p_.mass[i] = rho * src.volume[i];
    p_.planar_density[i] = geometric_weight(p_.position[i]) * rho;
    p_.reference_planar_density[i] = p_.planar_density[i];
    p_.spacing[i] = src.spacing[i];
    p_.smoothing_length[i] = options_.smoothing_factor * src.spacing[i];
    p_.reference_smoothing_length[i] = p_.smoothing_length[i];
    h_min = std::min(h_min, p_.smoothing_length[i]);
  }
  skin_ = n ? options_.skin_factor * h_min : 0.0;
  active_.set_skin(std::min(skin_, n ? 0.1 * h_min : 0.0));
  gather_material_state();
}

// SPH soil parts with `geostatic = {...}` start in their overburden state at each particle
// (model/geostatic_stress.hpp, as the FEM parts do at their element centres); the particle keeps
// its fill volume, so its mass carries the compressed weight.
template <int D>
void SphSystem<D>::set_geostatic_state(const Model& model) {
  set_geostatic_states(model, PartKind::sph, "particle", batches_,
                       [&](std::size_t part, std::vector<GeostaticPoint>& points, std::vector<std::size_t>& ids) {
                         for (std::size_t i = 0; i < p_.real; ++i) {
                           if (static_cast<std::size_t>(p_.part[i]) != part) continue;
                           GeostaticPoint point{p_.slot[i], {}};
                           for (int d = 0; d < D; ++d) point.centre[static_cast<std::size_t>(d)] = p_.position[i][d];
                           points.push_back(point);
                           ids.push_back(i + 1);
                         }
                       });
}

template <int D>
void SphSystem<D>::gather_material_state() {
  const std::size_t n = p_.real;
  std::size_t bad = 0;  // non-finite points; the serial search below names the first
  const bool smoothed_hoop = mode_ == GeometryMode::axisymmetric && options_.smoothed_hoop;
#pragma omp parallel for schedule(static) reduction(+ : bad)
  for (std::size_t i = 0; i < n; ++i) {
    const auto& pts = batches_[p_.material[i]];
    const std::size_t k = p_.slot[i];
    const double p = pts.pressure[k];
    SymTensor sigma = pts.deviator[k];
    sigma.xx -= p;
    sigma.yy -= p;
    sigma.zz -= p;
    p_.stress[i] = sigma;
    p_.pressure[i] = p;
    p_.wave_speed[i] = pts.wave_speed(k);
    p_.stable_wave_speed[i] = pts.stable_wave_speed(k);
    p_.plastic_strain[i] = pts.plastic_strain[k];
    p_.damage[i] = pts.damage[k];
    p_.temperature[i] = pts.temperature[k];
    // S = sigma / rho (= w sigma / eta while rho = eta / w; the smoothed hoop rate lets rho part from it).
    p_.stress_term[i] = sigma * (smoothed_hoop ? 1.0 / p_.density[i]
                                               : geometric_weight(p_.position[i]) / p_.planar_density[i]);
    if (!std::isfinite(p + sigma.xx + sigma.yy + sigma.xy + p_.wave_speed[i])) ++bad;
  }
  for (std::size_t i = 0; i < n && bad > 0; ++i)
    if (!std::isfinite(p_.pressure[i]) ||
        !std::isfinite(p_.stress[i].xx + p_.stress[i].yy + p_.stress[i].xy) ||
        !std::isfinite(p_.wave_speed[i]))
      throw NumericalError(
          EntityKind::particle, static_cast<std::int64_t>(p_.id[i]) + 1, "stress",
          fmt::format("non-finite stress or sound speed (density {:.6g} kg/m^3)", p_.density[i]));
}

template <int D>
void SphSystem<D>::refresh_ghosts() {
  const std::size_t n = p_.real;
  // The density form (volume_form = false) keeps |r| on the axis images (sph_options.hpp).
  const bool signed_images = options_.volume_form;
  image_sign_.resize(ghosts_.size());
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const std::size_t k = n + g, s = ghosts_[g].source;
    const MirrorPlane& plane = planes_[ghosts_[g].plane];
    p_.position[k] = mirror_position(p_.position[s], plane);
    p_.velocity[k] = mirror_velocity(p_.velocity[s], plane);
    if (velocity_old_.size() == p_.velocity.size())
      velocity_old_[k] = mirror_velocity(velocity_old_[s], plane);
    p_.mass[k] = p_.mass[s];
    p_.planar_density[k] = p_.planar_density[s];
    p_.smoothing_length[k] = p_.smoothing_length[s];
    p_.wave_speed[k] = p_.wave_speed[s];
    p_.viscosity_alpha[k] = p_.viscosity_alpha[s];
    p_.stress_term[k] = mirror_tensor(p_.stress_term[s], plane.axis);
    p_.tensile_term[k] = mirror_tensor(p_.tensile_term[s], plane.axis);
    image_sign_[g] = s >= n ? image_sign_[s - n] : 1;  // a ghost of a ghost inherits its source's side
    if (signed_images && plane.kind == PlaneKind::axis) {
      image_sign_[g] = static_cast<signed char>(-image_sign_[g]);
      // An image across the axis stands at r < 0: its ring weight w = 2 pi r is odd there,
      // so that r sigma continues smoothly (linearly) across the axis and the kernel sums of
      // div(r sigma) / r_i stay accurate in the first columns. With w = 2 pi |r| the images
      // made r sigma kinked at r = 0: the first column felt 1.41 x the vertical pressure
      // gradient and an outward push of ~0.5 p / r in uniform pressure (test_axis_gradient.cpp).
      p_.stress_term[k] = p_.stress_term[k] * -1.0;
      p_.tensile_term[k] = p_.tensile_term[k] * -1.0;
    }
    p_.correction[k] = mirror_tensor(p_.correction[s], plane.axis);
  }
  if (external_count_ > 0 && external_begin_ >= n && n > 0 &&
      p_.position.size() == external_begin_ + external_count_ && p_.velocity.size() == p_.position.size())
    external_provider_(p_, external_begin_);
}

template <int D>
void SphSystem<D>::prepare_neighbours() {
  const std::size_t n = p_.real;
  refresh_ghosts();
  if (!force_rebuild_ && !search_.needs_rebuild(p_.position, p_.smoothing_length)) return;
  force_rebuild_ = false;
  double h_max = 0.0;
#pragma omp parallel for schedule(static) reduction(max : h_max)
  for (std::size_t i = 0; i < n; ++i) h_max = std::max(h_max, p_.smoothing_length[i]);
  ghost_reach_ = support_factor * h_max + skin_;
  ghosts_ = make_ghosts(p_.position, n, planes_, ghost_reach_);
  external_begin_ = p_.position.size();  // coupling points after the ghosts
  p_.position.resize(external_begin_ + external_count_);
  const std::size_t total = p_.position.size();
  p_.velocity.resize(total);
  p_.mass.resize(total);
  p_.planar_density.resize(total);
  p_.smoothing_length.resize(total);
  p_.stress_term.resize(total);
  p_.tensile_term.resize(total);
  p_.wave_speed.resize(total);
  p_.stable_wave_speed.resize(total);
  p_.correction.resize(total, SymTensor::identity());
  p_.viscosity_alpha.resize(total, options_.viscosity_alpha);
  refresh_ghosts();
  search_.build(p_.position, p_.smoothing_length, n, skin_);
}

template <int D>
template <class T>
void SphSystem<D>::permute(std::vector<T>& a, const std::vector<std::uint32_t>& order) const {
  if (a.size() < order.size()) return;  // not allocated (e.g. v(n-1/2) before the first kick)
  std::vector<T> moved(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) moved[k] = a[order[k]];
  std::copy(moved.begin(), moved.end(), a.begin());
}

template <int D>
void SphSystem<D>::sort_by_cell() {
  const std::size_t n = p_.real;
  builds_at_sort_ = search_.builds();
  // order[k] = the particle that moves to index k: real particles in the cell
  // order of the last build (a stable counting sort by cell).
  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (const std::uint32_t i : search_.cell_order())
    if (i < n) order.push_back(i);
  if (order.size() != n) return;  // no build yet
  bool identity = true;
  for (std::size_t k = 0; k < n && identity; ++k) identity = order[k] == k;
  if (identity) return;
  auto& p = p_;
  permute(p.position, order);
  permute(p.velocity, order);
  permute(p.mass, order);
  permute(p.planar_density, order);
  permute(p.smoothing_length, order);
  permute(p.stress_term, order);
  permute(p.tensile_term, order);
  permute(p.wave_speed, order);
  permute(p.stable_wave_speed, order);
  permute(p.correction, order);
  permute(p.id, order);
  permute(p.acceleration, order);
  permute(p.displacement, order);
  permute(p.density, order);
  permute(p.reference_smoothing_length, order);
  permute(p.reference_planar_density, order);
  permute(p.spacing, order);
  permute(p.stress, order);
  permute(p.pressure, order);
  permute(p.plastic_strain, order);
  permute(p.damage, order);
  permute(p.temperature, order);
  permute(p.material, order);
  permute(p.part, order);
  permute(p.slot, order);
  permute(p.heating, order);
  permute(p.compression_rate, order);
  permute(p.viscosity_alpha, order);  // the viscosity switch's per-particle alpha
  permute(p.neighbour_count, order);
  permute(p.strain_rate, order);
  permute(p.spin, order);
  permute(velocity_old_, order);
  // The material batches stay in id order; their slots point at the new indices.
  for (std::size_t i = 0; i < n; ++i)
    batch_particles_[p.material[i]][p.slot[i]] = static_cast<std::uint32_t>(i);
  force_rebuild_ = true;                   // ghosts and lists refer to the old indices
  builds_at_sort_ = search_.builds() + 1;  // that forced rebuild does not count towards the next sort
  ++sorts_;
}

template <int D>
void SphSystem<D>::step(double dt, double time_end_of_step) {
  advance(dt);
  update_state(dt, time_end_of_step);
  compute_accelerations();
}

template <int D>
TimeStepLimit SphSystem<D>::stable_time_step() const {
  TimeStepLimit best{std::numeric_limits<double>::infinity(), "no particles"};
  std::size_t which = 0;
  const std::size_t n = p_.real;
  // In parallel, the smallest step and, among equal ones, the first particle: what the serial
  // loop finds, for any thread count.
#pragma omp parallel if (n > 4096)
  {
    double dt_min = std::numeric_limits<double>::infinity();
    std::size_t i_min = n;
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < n; ++i) {
      const double c = p_.wave_speed[i];
      const double speed =
          p_.stable_wave_speed[i] + norm(p_.velocity[i]) +
          0.6 * (options_.viscosity_alpha * c + options_.viscosity_beta * p_.compression_rate[i]);
      const double dt =
          speed > 0.0 ? p_.smoothing_length[i] / speed : std::numeric_limits<double>::infinity();
      if (dt < dt_min) dt_min = dt, i_min = i;
    }
#pragma omp critical(camouflet_sph_stable_step)
    if (i_min < n && (dt_min < best.dt || (dt_min == best.dt && i_min < which)))
      best.dt = dt_min, which = i_min;
  }
  if (p_.real && std::isfinite(best.dt))
    best.reason = fmt::format("particle {} ({}): h/(c+|v|+viscosity)", p_.id[which] + 1,
                              materials_[p_.material[which]]->name());
  return best;
}

template <int D>
void SphSystem<D>::scale_velocities(double factor) {
  for (Vec<D>& v : p_.velocity) v = v * factor;
}

template <int D>
void SphSystem<D>::hold_still(const std::vector<char>& held_material) {
  for (std::size_t k = 0; k < p_.real; ++k)
    if (held_material[static_cast<std::size_t>(p_.material[k])]) p_.velocity[k] = Vec<D>{};
}

template <int D>
void SphSystem<D>::come_to_rest() {
  for (auto* field : {&p_.velocity, &velocity_old_, &p_.displacement})
    for (Vec<D>& v : *field) v = Vec<D>{};
}

template <int D>
double SphSystem<D>::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < p_.real; ++i) e += 0.5 * p_.mass[i] * dot(p_.velocity[i], p_.velocity[i]);
  return e;
}

template <int D>
double SphSystem<D>::centred_kinetic_energy() const {
  if (velocity_old_.size() < p_.real) return kinetic_energy();
  double e = 0.0;
  for (std::size_t i = 0; i < p_.real; ++i) e += 0.5 * p_.mass[i] * dot(velocity_old_[i], p_.velocity[i]);
  return e;
}

template <int D>
double SphSystem<D>::internal_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < p_.real; ++i)
    e += p_.mass[i] * batches_[p_.material[i]].specific_energy[p_.slot[i]];
  return e;
}

template <int D>
Vec<D> SphSystem<D>::momentum() const {
  Vec<D> m{};
  for (std::size_t i = 0; i < p_.real; ++i) m += p_.velocity[i] * p_.mass[i];
  return m;
}

template <int D>
void SphSystem<D>::fill_snapshot(FieldSnapshot& s) const {
  static_assert(sizeof(Vec<D>) == D * sizeof(double), "Vec<D> must be D packed doubles");
  const std::size_t n = p_.real;
  auto flat = [n](const std::vector<Vec<D>>& v) {
    return std::span<const double>(reinterpret_cast<const double*>(v.data()), D * n);
  };
  // The snapshot's views of one set of particle arrays (the particles' own, or
  // their copies in id order); smoothing length and mass are also held by
  // ghosts and coupling points beyond the first n entries.
  auto publish = [&](const auto& a) {
    s.particle_position = flat(a.position);
    s.particle_displacement = flat(a.displacement);
    s.particle_velocity = flat(a.velocity);
    s.particle_acceleration = flat(a.acceleration);
    s.particle_density = a.density;
    s.particle_pressure = a.pressure;
    s.particle_stress = a.stress;
    s.particle_plastic_strain = a.plastic_strain;
    s.particle_damage = a.damage;
    s.particle_temperature = a.temperature;
    s.particle_material = a.material;
    s.particle_smoothing_length = std::span<const double>(a.smoothing_length.data(), n);
    s.particle_neighbour_count = a.neighbour_count;
    s.particle_mass = std::span<const double>(a.mass.data(), n);
  };
  if (sorts_ > 0) {
    // Memory order differs from id order: gather copies by id.
    auto& c = id_order_;
    auto by_id = [&](auto& out, const auto& in) {
      out.resize(n);
      for (std::size_t i = 0; i < n; ++i) out[p_.id[i]] = in[i];
    };
    by_id(c.position, p_.position);
    by_id(c.displacement, p_.displacement);
    by_id(c.velocity, p_.velocity);
    by_id(c.acceleration, p_.acceleration);
    by_id(c.density, p_.density);
    by_id(c.pressure, p_.pressure);
    by_id(c.stress, p_.stress);
    by_id(c.plastic_strain, p_.plastic_strain);
    by_id(c.damage, p_.damage);
    by_id(c.temperature, p_.temperature);
    by_id(c.material, p_.material);
    by_id(c.smoothing_length, p_.smoothing_length);
    by_id(c.neighbour_count, p_.neighbour_count);
    by_id(c.mass, p_.mass);
    publish(c);
    return;
  }
  publish(p_);
}

template class SphSystem<2>;
template class SphSystem<3>;

}  // namespace camouflet::sph
