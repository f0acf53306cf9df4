// In-structure shock as the mean free-field peak over the structure's span
// (Wang et al. 2005 §5.5): the paper's printed averages, and the closed-form
// integral against quadrature.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "core/error.hpp"
#include "empirical/ground_shock.hpp"
#include "empirical/imperial_units.hpp"
#include "empirical/shock_peaks.hpp"

using namespace camouflet;
using namespace camouflet::empirical;
namespace imp = camouflet::empirical::imperial;

namespace {

// Composite Simpson mean of a power law over [r1, r2]: an independent check of the closed form.
double simpson_mean(const PowerLaw& q, const Charge& c, double r1, double r2, int intervals = 4000) {
  const double h = (r2 - r1) / intervals;
  double sum = q.value(c.mass, c.coupling, r1) + q.value(c.mass, c.coupling, r2);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * q.value(c.mass, c.coupling, r1 + i * h);
  return sum * h / 3.0 / (r2 - r1);
}

}  // namespace

// 100 kg TNT, f = 0.6, structure from 6 m to 10 m (Wang et al. 2005 §5, §5.5).
TEST(InStructureShock, ReproducesThePapersAverages) {
  const Charge charge{100.0, 0.6};
  const ShockPeaks n2 = in_structure_shock(wang2005(2.0), charge, 6.0, 10.0);
  const ShockPeaks n25 = in_structure_shock(wang2005(2.5), charge, 6.0, 10.0);
  const std::string ref = "Wang et al. 2005 §5.5, printed";
  test::verify({"In-structure shock, paper case: V_avg (n = 2)", ref, 1.59, n2.velocity, 0.01, true, "m/s"});
  test::verify(
      {"In-structure shock, paper case: V_avg (n = 2.5)", ref, 0.78, n25.velocity, 0.01, true, "m/s"});
  test::verify({"In-structure shock, paper case: a_avg (n = 2)", ref, 311.0,
                n2.acceleration / imp::standard_gravity, 0.01, true, "g"});
  test::verify({"In-structure shock, paper case: a_avg (n = 2.5)", ref, 154.0,
                n25.acceleration / imp::standard_gravity, 0.01, true, "g"});
}

TEST(InStructureShock, ClosedFormMatchesQuadrature) {
  const Charge charge{250.0, 0.8};
  // n = 2.3: four different exponents; n = 2: displacement decays as Z^-1 (the
  // logarithm branch); n = 2 + 1e-9: just beside it.
  for (double n : {2.3, 2.0, 2.0 + 1e-9}) {
    const GroundShockLaw law = tm5_855_1(Soil{1700.0, 900.0}, n);
    for (const PowerLaw* q : {&law.stress, &law.velocity, &law.acceleration, &law.displacement}) {
      const double exact = q->span_average(charge.mass, charge.coupling, 3.0, 12.0);
      const double numeric = simpson_mean(*q, charge, 3.0, 12.0);
      test::verify(
          {fmt::format("Span average vs Simpson quadrature, n = {}, exponent m = {}", n, q->range_exponent),
           "composite Simpson, 4000 intervals", numeric, exact, 1e-9, true, "SI"});
    }
  }
}

TEST(InStructureShock, NarrowSpanTendsToThePointValue) {
  const Charge charge{100.0, 0.6};
  const GroundShockLaw law = wang2005(2.5);
  const double mean = law.velocity.span_average(charge.mass, charge.coupling, 7.0, 7.0 + 1e-6);
  const double point = law.velocity.value(charge.mass, charge.coupling, 7.0 + 0.5e-6);
  test::verify({"Span average over a vanishing span", "the free-field value at its centre", point, mean, 1e-9,
                true, "m/s"});
}

TEST(InStructureShock, RefusesBadSpans) {
  const Charge charge{100.0, 0.6};
  const GroundShockLaw law = wang2005(2.0);
  EXPECT_THROW(in_structure_shock(law, charge, 10.0, 6.0), InputError);
  EXPECT_THROW(in_structure_shock(law, charge, 6.0, 6.0), InputError);
  EXPECT_THROW(in_structure_shock(law, charge, -1.0, 6.0), InputError);
  EXPECT_THROW(in_structure_shock(law, Charge{0.0, 0.6}, 6.0, 10.0), InputError);
  EXPECT_THROW(in_structure_shock(law, Charge{100.0, 1.5}, 6.0, 10.0), InputError);
}
