#include <gtest/gtest.h>

#include "core/parameters.hpp"
#include "core/sym_tensor.hpp"

using namespace camouflet;

TEST(SymTensor, PrincipalValuesOfRotatedDiagonal) {
  // diag(3, 2, -1) rotated by 30 degrees about z.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double a = 3.0, b = 2.0;
  SymTensor t{a * c * c + b * s * s, a * s * s + b * c * c, -1.0, (a - b) * c * s, 0.0, 0.0};
  const auto e = principal_values(t);
  EXPECT_NEAR(e[0], 3.0, 1e-12);
  EXPECT_NEAR(e[1], 2.0, 1e-12);
  EXPECT_NEAR(e[2], -1.0, 1e-12);
}

TEST(SymTensor, JaumannRotationKeepsInvariants) {
  SymTensor s{1.0, -0.5, -0.5, 0.3, 0.0, 0.0};
  const Spin w{0.7, 0.0, 0.0};
  const SymTensor ds = jaumann_increment(s, w, 1e-3);
  // A pure rotation increment is orthogonal to s: s:ds = 0 and tr(ds) = 0.
  EXPECT_NEAR(contract(s, ds), 0.0, 1e-15);
  EXPECT_NEAR(ds.trace(), 0.0, 1e-15);
}

TEST(Parameters, UnknownKeySuggestsNearest) {
  Parameters p(SourceLocation{"case.toml", 4, 1, "materials.rock.eos"});
  p.set_number("densty", 2000.0, SourceLocation{"case.toml", 5, 1, "materials.rock.eos.densty"});
  p.set_number("bulk_modulus", 1e9, SourceLocation{"case.toml", 6, 1, "materials.rock.eos.bulk_modulus"});
  EXPECT_DOUBLE_EQ(p.number("bulk_modulus"), 1e9);
  EXPECT_DOUBLE_EQ(p.number("density", 1.0), 1.0);
  try {
    p.finish();
    FAIL() << "unknown key accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 5);
    EXPECT_NE(std::string(e.what()).find("did you mean 'density'"), std::string::npos) << e.what();
  }
}
