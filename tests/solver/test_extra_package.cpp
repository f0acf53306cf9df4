// A method added without editing the driver: a package of rigid point masses
// (model/package.hpp), registered with Solver::add_package beside an FEM block,
// falls under gravity as g t^2 / 2 and bounces elastically off the model's
// symmetry plane (a point meeting its mirror image there), with gravity's
// work on it in the energy balance; its presence leaves the FEM block's motion
// bit for bit; its state goes through the checkpoint visitor and back.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "boundary/mirror_planes.hpp"
#include "checkpoint/checkpoint_data.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double g = 9.81;  // m/s^2

// Point masses moved by gravity alone, reflected at every symmetry plane of the model: a point
// that crosses a plane within a drift is put back at its mirror position with its normal
// velocity reversed (what its mirror image would do to it in an elastic impact).
template <int D>
class RigidPoints : public Package<D> {
 public:
  RigidPoints(std::vector<sph::MirrorPlane> planes, std::vector<double> x, std::vector<double> v,
              std::vector<double> m)
      : planes_(std::move(planes)), x_(std::move(x)), v_(std::move(v)), m_(std::move(m)) {
    v_old_ = v_;
    a_.assign(x_.size(), 0.0);
    for (const sph::MirrorPlane& p : planes_)  // the side of each plane the points start on
      side_.push_back(x_[static_cast<std::size_t>(p.axis)] >= p.position ? 1.0 : -1.0);
  }
  std::string name() const override { return "rigid_points"; }
  void add_forces(const StepClock&) override { std::fill(a_.begin(), a_.end(), 0.0); }
  void add_gravity(const std::array<double, 3>& gravity, double& power) override {
    for (std::size_t k = 0; k < m_.size(); ++k)
      for (int i = 0; i < D; ++i) {
        a_[k * D + i] += gravity[static_cast<std::size_t>(i)];
        power += m_[k] * gravity[static_cast<std::size_t>(i)] * v_[k * D + i];
      }
  }
  void kick(const StepClock& clock) override {
    v_old_ = v_;
    for (std::size_t k = 0; k < v_.size(); ++k) v_[k] += a_[k] * clock.dt_mean();
  }
  double drift(const StepClock& clock) override {
    // The step that ended at t_n (dt_minus) and the one being taken (dt).
    const double dt_minus = clock.dt, dt = clock.dt_next;
    // The centred kinetic energy of the nodes (FemPackage::drift): (1/2) m (v_n^2 - a^2 dt-^2 / 4)
    // with v_n = v(n-1/2) + a dt- / 2.
    double kinetic = 0.0;
    for (std::size_t k = 0; k < m_.size(); ++k)
      for (int i = 0; i < D; ++i) {
        const double a = a_[k * D + i], vn = v_old_[k * D + i] + 0.5 * a * dt_minus;
        kinetic += 0.5 * m_[k] * (vn * vn - 0.25 * a * a * dt_minus * dt_minus);
      }
    for (std::size_t k = 0; k < x_.size(); ++k) x_[k] += v_[k] * dt;
    for (std::size_t k = 0; k < m_.size(); ++k)
      for (std::size_t p = 0; p < planes_.size(); ++p) {
        const std::size_t c = k * D + static_cast<std::size_t>(planes_[p].axis);
        if ((x_[c] - planes_[p].position) * side_[p] < 0.0) {
          x_[c] = 2.0 * planes_[p].position - x_[c];
          v_[c] = -v_[c];
          ++bounces_;
        }
      }
    return kinetic;
  }
  void update_state(const StepClock&, EnergyBalance&) override {}
  typename Package<D>::Vote vote() const override { return {std::numeric_limits<double>::infinity(), "none", EntityKind::model, 0, ""}; }
  double kinetic_energy() const override {
    double e = 0.0;
    for (std::size_t k = 0; k < m_.size(); ++k)
      for (int i = 0; i < D; ++i) e += 0.5 * m_[k] * v_[k * D + i] * v_[k * D + i];
    return e;
  }
  double internal_energy() const override { return 0.0; }
  void check() const override {
    for (std::size_t k = 0; k < x_.size(); ++k)
      if (!std::isfinite(x_[k]) || !std::isfinite(v_[k]))
        throw NumericalError(EntityKind::model, 0, "rigid point velocity",
                             fmt::format("point {}: non-finite position or velocity", k / D + 1));
  }
  void visit_state(StateVisitor& visitor) override {
    StateScope scope(visitor, "package." + name());
    visit(visitor, "position", x_);
    visit(visitor, "velocity", v_);
    visit(visitor, "velocity_old", v_old_);
    visit(visitor, "acceleration", a_);
    visit(visitor, "bounces", bounces_);
  }

  const std::vector<double>& position() const { return x_; }
  const std::vector<double>& velocity() const { return v_; }
  std::int64_t bounces() const { return bounces_; }

 private:
  std::vector<sph::MirrorPlane> planes_;
  std::vector<double> side_;
  std::vector<double> x_, v_, v_old_, a_, m_;
  std::int64_t bounces_ = 0;
};

// An elastic block resting on the symmetry plane y = 0 (3-D: z = 0) under gravity, apart from
// where the point falls.
template <int D>
Model block_on_symmetry_plane() {
  const GeometryMode mode = D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d;
  const std::array<double, 3> size = D == 2 ? std::array<double, 3>{0.2, 0.2, 0.0} : std::array<double, 3>{0.2, 0.2, 0.2};
  // In 3-D the block stands on z = 0: its base is the zmin set.
  Model model = test::block_model(mode, {{"block", 0, {1.0, 0, 0}, size, {2, 2, 2}}}, test::ElasticConstants{});
  const std::array<double, 3> up = D == 2 ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{0, 0, 1};
  model.boundaries.push_back(test::symmetry(D == 2 ? "block.ymin" : "block.zmin", up));
  model.run.gravity = {};
  model.run.gravity[static_cast<std::size_t>(D - 1)] = -g;
  return model;
}

template <int D>
void expect_fall_and_bounce(const std::string& label) {
  test::use_threads(1);
  const Model model = block_on_symmetry_plane<D>();
  const double h = 0.5;               // m, drop height above the plane
  const double t_hit = std::sqrt(2.0 * h / g);  // s
  const double mass = 2.0;            // kg
  std::vector<double> x(D, 0.0), v(D, 0.0);
  x[D - 1] = h;
  Solver<D> with(model), without(model);
  auto points = std::make_unique<RigidPoints<D>>(sph::symmetry_mirror_planes(model), x, v, std::vector<double>{mass});
  const RigidPoints<D>& p = *points;
  with.add_package(std::move(points));
  EXPECT_THROW(with.relax({0.1, 1e-4, 1.0, {}}), std::logic_error)
      << "a relaxation refuses a package it would not damp";
  EXPECT_THROW(with.add_package(std::make_unique<RigidPoints<D>>(sph::symmetry_mirror_planes(model), x, v,
                                                                 std::vector<double>{mass})),
               std::logic_error)
      << "a second package of the same name is refused";

  // Before the bounce: the central difference integrates a constant acceleration exactly.
  const double t_before = 0.6 * t_hit;
  double dt_max = 0.0;
  while (with.time() < t_before) {
    with.step();
    without.step();
    dt_max = std::max(dt_max, with.time_step_limit().dt);
  }
  const double t1 = with.time();
  test::verify({label + ": height of the point before its bounce", "h - g t^2 / 2 (analytic)",
                h - 0.5 * g * t1 * t1, p.position()[D - 1], 1e-9, true, "m"});

  // After the bounce, at 1.5 t_hit: back up at v = g t_hit, y = g t_hit s - g s^2 / 2 with
  // s = t - t_hit. Reflecting within a step moves the velocity reversal by up to dt / 2, so the
  // first-order bound is g dt / 2 (t - t_hit) + g dt^2.
  const double t_end = 1.5 * t_hit;
  while (with.time() < t_end) {
    with.step();
    without.step();
    dt_max = std::max(dt_max, with.time_step_limit().dt);
  }
  const double t2 = with.time(), s = t2 - t_hit;
  const double expected = g * t_hit * s - 0.5 * g * s * s;
  const double bound = 0.5 * g * dt_max * s + g * dt_max * dt_max;
  test::verify({label + ": height of the point after one bounce off the symmetry plane",
                "g t* s - g s^2 / 2 (analytic, elastic bounce)", expected, p.position()[D - 1], bound / expected,
                true, "m"});
  EXPECT_EQ(p.bounces(), 1);
  // Gravity's work on the point is booked: the balance closes over the fall and the bounce to
  // the work booked on the reflecting step, which takes the point's path as v dt where it went
  // down by y and up by v dt - y (0 <= y <= |v| dt): at most 2 m g |v| dt, beside the block's own
  // error (the same model without the point).
  auto absolute_error = [](const EnergyBalance& e) {
    const double total = e.kinetic + e.internal + e.hourglass + e.eroded;
    return e.relative_error * std::max(e.initial_total + std::abs(e.boundary_work), std::abs(total));
  };
  const double energy_bound = 2.0 * mass * g * (g * t_hit) * dt_max + absolute_error(without.energy());
  test::verify({label + ": energy balance with the point's fall and bounce",
                "closed to the reflecting step's work, 2 m g |v| dt", 0.0, absolute_error(with.energy()),
                energy_bound, false, "J"});
  EXPECT_GT(with.energy_split().gravity, without.energy_split().gravity);

  // The block does not know the point is there.
  const bool same = with.position().size() == without.position().size() &&
                    std::memcmp(with.position().data(), without.position().data(),
                                with.position().size() * sizeof(double)) == 0 &&
                    std::memcmp(with.velocity().data(), without.velocity().data(),
                                with.velocity().size() * sizeof(double)) == 0;
  test::record_check(label + ": FEM block with the package registered vs without, node positions and velocities",
                     "bit-identical", same ? "bit-identical" : "differ", same);
  EXPECT_TRUE(same);
  EXPECT_THROW(with.add_package(std::make_unique<RigidPoints<D>>(sph::symmetry_mirror_planes(model), x, v,
                                                                 std::vector<double>{mass})),
               std::logic_error)
      << "packages are registered before the first step";
}

TEST(ExtraPackage, RigidPointsFallAndBounceBesideAnFemBlockPlaneStrain) {
  expect_fall_and_bounce<2>("Rigid point package beside FEM, plane strain");
}

TEST(ExtraPackage, RigidPointsFallAndBounceBesideAnFemBlock3d) {
  expect_fall_and_bounce<3>("Rigid point package beside FEM, 3-D");
}

// The package's state is part of the solver's: recorded after 200 cycles into a checkpoint in
// memory, loaded into a fresh solver with its own package, both runs end bit-identical.
TEST(ExtraPackage, StateGoesThroughTheCheckpointVisitor) {
  test::use_threads(1);
  const Model model = block_on_symmetry_plane<2>();
  auto make = [&](Solver<2>& solver) {
    auto points = std::make_unique<RigidPoints<2>>(sph::symmetry_mirror_planes(model), std::vector<double>{0.0, 0.3},
                                                   std::vector<double>{0.0, 1.0}, std::vector<double>{1.0});
    const RigidPoints<2>* raw = points.get();
    solver.add_package(std::move(points));
    return raw;
  };
  Solver<2> first(model), second(model);
  const RigidPoints<2>* a = make(first);
  const RigidPoints<2>* b = make(second);
  for (int k = 0; k < 200; ++k) first.step();
  CheckpointData data;
  StateRecorder recorder(data);
  first.visit_state(recorder);
  EXPECT_TRUE(data.arrays.count("solver.package.rigid_points.position") == 1)
      << "the package's state is recorded under its name";
  StateLoader loader(data);
  second.visit_state(loader);
  loader.finish();
  for (int k = 0; k < 300; ++k) {
    first.step();
    second.step();
  }
  EXPECT_EQ(std::memcmp(a->position().data(), b->position().data(), 2 * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a->velocity().data(), b->velocity().data(), 2 * sizeof(double)), 0);
  EXPECT_EQ(first.time(), second.time());
}

}  // namespace
