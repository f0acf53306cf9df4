// Element colouring for the force assembly (fem/element_colouring.hpp):
// the colouring itself (every element once, no two elements, or blocks of
// elements, of a colour sharing a node), and the assemblies of
// FemElements::add_internal_forces (colour blocks) and the two kept for
// comparison in bench/fem_assemblies.hpp: per-thread buffers and colours
// (single elements or blocks) give the same nodal forces to round-off
// (1e-12 relative), and the colour assemblies the same bits on 1 and 2 threads
// (each node sums its elements in colour order whatever the threads).
// Meshes: distorted blocks of 16^3 hexes and 64 x 64 axisymmetric quads, above
// the parallel threshold of fem/parallel.hpp so that 2 threads really share them.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "../../bench/bench_problems.hpp"
#include "../../bench/fem_assemblies.hpp"
#include "common/history_difference.hpp"
#include "common/verification.hpp"
#include "fem/element_colouring.hpp"
#include "fem/fem_elements.hpp"
#include "fem/parallel.hpp"

using namespace camouflet;
using camouflet::test::relative_difference;

namespace {

// The benchmark meshes (bench_problems.hpp), interior nodes moved by up to 20 % of a cell.
FemMesh distorted_mesh(int dimension) {
  FemMesh mesh = dimension == 3 ? bench::hex_impact_model(16 * 16 * 16).mesh
                                : bench::soil_axisymmetric_model(2 * 45 * 45).mesh;
  std::mt19937 rng(2026);
  const double cell = dimension == 3 ? 0.045 / 16 : 1.0 / 45;
  std::uniform_real_distribution<double> u(-0.2 * cell, 0.2 * cell);
  const std::size_t d = static_cast<std::size_t>(dimension);
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    for (std::size_t i = 0; i < d; ++i) {
      double& x = mesh.coordinates[n * d + i];
      const double lo = i == 1 && dimension == 2 ? -2.0 : 0.0;
      const double hi = dimension == 3 ? 0.045 : (i == 0 ? 1.0 : 0.0);
      if (x > lo + 1e-9 && x < hi - 1e-9) x += u(rng);
    }
  return mesh;
}

template <int D>
struct ForceCase {
  FemMesh mesh = distorted_mesh(D);
  std::vector<double> velocity;

  ForceCase() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    velocity.resize(mesh.coordinates.size());
    for (double& v : velocity) v = 10.0 * u(rng);  // m/s
  }

  // Elements with a random stress, q and material state (the same draw every call).
  FemElements<D> elements() const {
    FemElements<D> el(mesh, D == 2 ? GeometryMode::axisymmetric : GeometryMode::three_d, mesh.coordinates);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t e = 0; e < el.size(); ++e) {
      el.stress[e] = SymTensor{1e8 * u(rng), 1e8 * u(rng), 1e8 * u(rng),
                               5e7 * u(rng), 5e7 * u(rng), 5e7 * u(rng)};  // Pa
      el.viscosity[e] = 1e6 * (1.0 + u(rng));                              // Pa
      el.density[e] = 2000.0 * (1.0 + 0.1 * u(rng));                       // kg/m^3
      el.wave_speed[e] = 1500.0 * (1.0 + 0.1 * u(rng));                    // m/s
    }
    return el;
  }

  // Nodal forces and hourglass forces of two calls (the stiffness form needs a second call
  // to have displacements to resist), on `threads` threads; the stored energy appended.
  std::vector<double> forces(bench::Assembly assembly, HourglassForm form, int threads) const {
    omp_set_num_threads(threads);
    FemElements<D> el = elements();
    bench::AssemblyScratch scratch;
    const std::size_t values = mesh.coordinates.size();
    std::vector<double> f(values, 0.0), fh(values, 0.0);
    const HourglassControl hg{form, 0.1};
    double stored = 0.0;
    for (int call = 0; call < 2; ++call)
      stored = bench::add_internal_forces(assembly, el, mesh.coordinates.data(), velocity.data(), f.data(),
                                          fh.data(), hg, 1e-6, scratch);
    f.insert(f.end(), fh.begin(), fh.end());
    f.push_back(stored);
    return f;
  }
};

template <int D>
void check_colouring(const std::string& name, std::size_t block, std::size_t expected_colours) {
  const FemMesh mesh = distorted_mesh(D);
  const ElementColouring colouring =
      colour_elements(mesh.connectivity, mesh.nodes_per_element, mesh.node_count(), block);
  const std::size_t ne = mesh.element_count();
  ASSERT_GT(ne, static_cast<std::size_t>(parallel_threshold));
  ASSERT_EQ(colouring.block, block);
  std::vector<int> seen(ne, 0);
  bool shared = false;
  for (std::size_t c = 0; c < colouring.colours(); ++c) {
    std::vector<std::size_t> node_block(mesh.node_count(),
                                        ne);  // the block of this colour that uses the node
    for (std::size_t k = colouring.begin[c]; k < colouring.begin[c + 1]; ++k) {
      const std::size_t b = colouring.blocks[k];
      if (k > colouring.begin[c]) {
        EXPECT_LT(colouring.blocks[k - 1], b);  // ascending within a colour
      }
      for (std::size_t e = b * block; e < std::min(ne, (b + 1) * block); ++e) {
        ++seen[e];
        for (int a = 0; a < mesh.nodes_per_element; ++a) {
          std::size_t& user =
              node_block[static_cast<std::size_t>(mesh.connectivity[e * mesh.nodes_per_element + a])];
          shared = shared || (user != ne && user != b);
          user = b;
        }
      }
    }
  }
  EXPECT_FALSE(shared) << "two elements (blocks) of one colour share a node";
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }))
      << "an element is missing or coloured twice";
  EXPECT_EQ(colouring.colours(), expected_colours);
  test::record_check(name + ": element colouring, blocks of " + std::to_string(block) + " (" +
                         std::to_string(ne) + " elements, " + std::to_string(colouring.colours()) +
                         " colours)",
                     "every element in exactly one colour, no two elements (blocks) of a colour share a node",
                     shared ? "a node shared within a colour" : "holds", !shared);
}

template <int D>
void check_assemblies(const std::string& name, HourglassForm form) {
  const ForceCase<D> problem;
  const int threads_before = omp_get_max_threads();
  const auto buffers_1 = problem.forces(bench::Assembly::buffers, form, 1);
  const auto buffers_2 = problem.forces(bench::Assembly::buffers, form, 2);
  EXPECT_GT(*std::max_element(buffers_1.begin(), buffers_1.end()), 1.0);  // not trivially zero
  for (const bench::Assembly assembly :
       {bench::Assembly::colours, bench::Assembly::colour_blocks, bench::Assembly::element_order}) {
    const std::string kind = assembly == bench::Assembly::colours         ? "colour"
                             : assembly == bench::Assembly::colour_blocks ? "colour-block"
                                                                          : "element-order";
    const auto colours_1 = problem.forces(assembly, form, 1);
    const auto colours_2 = problem.forces(assembly, form, 2);
    test::verify({name + ": nodal forces, " + kind + " assembly against per-thread buffers (1 thread)",
                  "the same element forces summed in another order (round-off)", 0.0,
                  relative_difference(buffers_1, colours_1), 1e-12, false, "relative"});
    test::verify({name + ": nodal forces, " + kind + " assembly against per-thread buffers (2 threads)",
                  "the same element forces summed in another order (round-off)", 0.0,
                  relative_difference(buffers_2, colours_2), 1e-12, false, "relative"});
    // Each node adds its elements in colour (element) order on any thread count: the same bits.
    test::verify({name + ": nodal forces, " + kind + " assembly on 1 and 2 threads", "bit-identical", 0.0,
                  relative_difference(colours_1, colours_2), 0.0, false, "relative"});
    EXPECT_TRUE(colours_1 == colours_2);
  }
  omp_set_num_threads(threads_before);
}

}  // namespace

// Greedy colouring of a structured block in element order: single elements need 2^D colours (node
// valence 2^D); blocks of 512 elements (two 16 x 16 planes of hexes, 11.4 rows of 45 quads) conflict
// only with the blocks before and after them: 2 colours. The default block sizes of these meshes:
// 64 hexes (4 rows of 16) need 4 colours, 56 quads (1.2 rows of 45) still 2.
TEST(ElementColouring, HexBlockNoTwoElementsOfAColourShareANode) {
  check_colouring<3>("hex8 block 16^3, distorted", 1, 8);
  check_colouring<3>("hex8 block 16^3, distorted", 512, 2);
  ASSERT_EQ(colour_block_size(4096), 64u);
  check_colouring<3>("hex8 block 16^3, distorted", 64, 4);
}

TEST(ElementColouring, QuadBlockNoTwoElementsOfAColourShareANode) {
  check_colouring<2>("quad block 45 x 90, distorted", 1, 4);
  check_colouring<2>("quad block 45 x 90, distorted", 512, 2);
  ASSERT_EQ(colour_block_size(4050), 56u);
  check_colouring<2>("quad block 45 x 90, distorted", 56, 2);
}

TEST(ElementColouring, BlockSizeDependsOnTheMeshOnly) {
  EXPECT_EQ(colour_block_size(91125), 512u);  // capped
  EXPECT_EQ(colour_block_size(5000), 72u);    // at least 64 blocks, a multiple of 8
  EXPECT_EQ(colour_block_size(100), 8u);      // at least one pack of 8
}

TEST(ElementColouring, HexAssembliesAgreeViscousHourglass) {
  check_assemblies<3>("hex8 block 16^3, viscous hourglass control", HourglassForm::viscous);
}

TEST(ElementColouring, HexAssembliesAgreeStiffnessHourglass) {
  check_assemblies<3>("hex8 block 16^3, stiffness hourglass control", HourglassForm::stiffness);
}

TEST(ElementColouring, AxisymmetricQuadAssembliesAgree) {
  check_assemblies<2>("r-z quad block 45 x 90, viscous hourglass control", HourglassForm::viscous);
}
