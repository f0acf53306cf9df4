// Linear EOS, elastic and von Mises strength at one material point along a
// uniaxial-strain compression path, against closed forms.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "common/verification.hpp"
#include "materials/elastic_strength.hpp"
#include "materials/linear_eos.hpp"
#include "materials/registry.hpp"

using namespace camouflet;

namespace {

constexpr double rho0 = 7800.0, bulk = 160e9, shear = 80e9, yield = 400e6;

Parameters block(std::initializer_list<std::pair<const char*, double>> numbers, const std::string& type) {
  Parameters p(SourceLocation{"case.toml", 7, 1, "materials.steel"});
  p.set_string("type", type);
  for (const auto& [k, v] : numbers) p.set_number(k, v);
  return p;
}

struct PathResult {
  double strain = 0.0;  // logarithmic compressive strain reached
  double pressure = 0.0, sxx = 0.0, plastic_strain = 0.0;
};

// Uniaxial strain D = diag(-rate, 0, 0) for `steps` steps of dt.
PathResult compress(const Material& m, double rate, double dt, int steps) {
  omp_set_num_threads(1);  // one point: a thread team would only cost time
  MaterialPoints pts;
  m.setup(pts, 1);
  double strain = 0.0;
  for (int k = 0; k < steps; ++k) {
    strain += rate * dt;
    pts.density_previous[0] = pts.density[0];
    pts.density[0] = rho0 * std::exp(strain);  // rho / rho0 = exp(volumetric log strain)
    pts.strain_rate[0] = SymTensor{-rate, 0, 0, 0, 0, 0};
    m.update(pts, MaterialContext{dt, (k + 1) * dt});
  }
  return {strain, pts.pressure[0], pts.deviator[0].xx, pts.plastic_strain[0]};
}

}  // namespace

TEST(LinearElastic, UniaxialStrainMatchesHookeAndLinearEos) {
  // Built from the classes directly (this also links their registrations
  // into this test executable for the registry tests below).
  const auto m = std::make_shared<const Material>("steel", std::make_shared<const LinearEos>(rho0, bulk),
                                                  std::make_shared<const ElasticStrength>(shear));
  const PathResult r = compress(*m, 10.0, 1e-6, 200);  // 0.2 % strain
  test::verify({"Linear EOS, uniaxial strain: pressure", "K (rho/rho0 - 1)",
                bulk * (std::exp(r.strain) - 1.0), r.pressure, 1e-12, true, "Pa"});
  test::verify({"Elastic strength, uniaxial strain: deviator s_xx", "-(4/3) G eps (hypoelastic, log strain)",
                -4.0 / 3.0 * shear * r.strain, r.sxx, 1e-12, true, "Pa"});
}

TEST(VonMises, UniaxialStrainYieldsAtTwoThirdsYAndAccumulatesPlasticStrain) {
  Parameters eos = block({{"density", rho0}, {"bulk_modulus", bulk}}, "linear");
  Parameters strength = block({{"shear_modulus", shear}, {"yield_stress", yield}}, "von_mises");
  const auto m = make_material("steel", "", {}, eos, strength, Parameters{});
  const PathResult r = compress(*m, 10.0, 1e-6, 1000);  // 1 %, yield at Y / 2G = 0.25 %
  const double strain_at_yield = yield / (2.0 * shear);
  test::verify({"von Mises, uniaxial strain: deviator on the yield surface",
                "s_xx = -(2/3) Y (perfect plasticity)", -2.0 / 3.0 * yield, r.sxx, 1e-12, true, "Pa"});
  test::verify({"von Mises, uniaxial strain: effective plastic strain", "(2/3)(eps - Y/2G) (radial return)",
                2.0 / 3.0 * (r.strain - strain_at_yield), r.plastic_strain, 0.01, true, "-"});
  // Below the elastic limit it is the elastic law.
  const PathResult e = compress(*m, 10.0, 1e-6, 200);
  EXPECT_NEAR(e.sxx, -4.0 / 3.0 * shear * e.strain, 1e-9 * shear);
  EXPECT_EQ(e.plastic_strain, 0.0);
}

TEST(MaterialRegistry, MisspeltKeyIsRefusedWithSuggestion) {
  Parameters eos = block({{"density", rho0}, {"bulk_modulu", bulk}}, "linear");
  try {
    make_eos(eos);
    FAIL() << "a misspelt key must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bulk_modulus"), std::string::npos) << e.what();
  }
  Parameters bad = block({{"density", -1.0}, {"bulk_modulus", bulk}}, "linear");
  EXPECT_THROW(make_eos(bad), InputError);
  Parameters no_yield = block({{"shear_modulus", shear}}, "von_mises");
  EXPECT_THROW(make_strength(no_yield), InputError);
}
