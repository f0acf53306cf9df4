#pragma once
// The soils of the geostatic tests (test_geostatic_column.cpp, test_geostatic_sph.cpp): an
// elastic soil with a given K0 and the seed paper's sandy clay with Jaky's K0, each with the K0
// its state must show.
#include <cmath>
#include <memory>
#include <optional>

#include "common/fem_models.hpp"
#include "materials/registry.hpp"

namespace camouflet::test {

struct GeostaticSoil {
  std::shared_ptr<const Material> material;
  double density = 0.0;      // kg/m^3, reference
  std::optional<double> k0;  // none: Jaky
  double expected_k0 = 0.0;
};

inline GeostaticSoil elastic_soil() {
  ElasticConstants c;
  c.density = 1800.0;
  c.bulk_modulus = 1.0e8;
  c.shear_modulus = 6.0e7;
  return {elastic_material(c, "soil"), c.density, 0.5, 0.5};
}

// The seed paper's sandy clay: three-phase soil EOS, Drucker-Prager strength (alpha = 0.25:
// phi = 32.3 degrees, Jaky's K0 = 1 - sin(phi) = 0.466).
inline GeostaticSoil sandy_clay() {
  GeostaticSoil s;
  s.material = make_material("soil", "sandy_clay_wang2005", {}, Parameters{}, Parameters{}, Parameters{});
  s.density = s.material->reference_density();
  const double a = std::sqrt(3.0) * 0.25;
  s.expected_k0 = 1.0 - 3.0 * a / (2.0 + a);
  return s;
}

}  // namespace camouflet::test
