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

// The six-entry form must give the full product W s - s W (3x3 loops, the
// definition) bit for bit, for a general 3-D spin and stress.
TEST(SymTensor, JaumannIncrementIsTheFullMatrixProductBitForBit) {
  const SymTensor s{1.3e6, -0.7e6, 2.1e5, 0.37e6, -1.9e5, 0.83e6};
  const Spin w{0.71, -0.23, 0.47};
  const double dt = 3.1e-6;
  const double W[3][3] = {{0.0, w.xy, -w.zx}, {-w.xy, 0.0, w.yz}, {w.zx, -w.yz, 0.0}};
  const double S[3][3] = {{s.xx, s.xy, s.zx}, {s.xy, s.yy, s.yz}, {s.zx, s.yz, s.zz}};
  double R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double v = 0.0;
      for (int k = 0; k < 3; ++k) v += W[i][k] * S[k][j] - S[i][k] * W[k][j];
      R[i][j] = dt * v;
    }
  const SymTensor ds = jaumann_increment(s, w, dt);
  EXPECT_EQ(ds.xx, R[0][0]);
  EXPECT_EQ(ds.yy, R[1][1]);
  EXPECT_EQ(ds.zz, R[2][2]);
  EXPECT_EQ(ds.xy, R[0][1]);
  EXPECT_EQ(ds.yz, R[1][2]);
  EXPECT_EQ(ds.zx, R[2][0]);
  // Symmetric result: the entries not returned mirror the returned ones.
  EXPECT_EQ(R[1][0], R[0][1]);
  EXPECT_EQ(R[2][1], R[1][2]);
  EXPECT_EQ(R[0][2], R[2][0]);
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
