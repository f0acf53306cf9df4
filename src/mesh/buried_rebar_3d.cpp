// Reinforcement of the 3-D buried box (buried_structure_3d.cpp) as embedded
// bars ([[bars]], docs/theory/reinforcement.md §2): in each of the five walls
// of the half model (front, back, side, roof, floor; the other side wall is
// the mirror image) an outer mat at `cover` from the outer face and an inner
// mat at `cover` from the inner face, each a grid of bars in both directions
// of the wall's plane. Each bar stands for a strip of the mat about one
// structure cell wide (its centre line), with steel area ratio x thickness x
// strip width, so each direction carries ratio x thickness per metre as in the
// r-z mats. Mats run between the mats of the adjoining walls, as in r-z, and to
// the symmetry plane y = 0.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include "mesh/buried_structure_internal.hpp"

namespace camouflet::buried_detail {

namespace {

// A mat: the plane `axis` (0 = x, 1 = y, 2 = depth) = `at`, spanning
// [lo, hi] on the two other axes (coordinates in x, y, depth; entry `axis` unused).
struct Mat {
  std::string name;
  int axis;
  double at;
  std::array<double, 3> lo, hi;
};

const char* axis_letter(int axis) {
  return axis == 0 ? "x" : axis == 1 ? "y" : "z";
}

int strips(double length, double size) {
  return std::max(1, static_cast<int>(std::lround(length / size)));
}

}  // namespace

void write_rebar_3d(const BuriedStructureSpec& s, std::string& b) {
  auto out = std::back_inserter(b);
  const double c = s.rebar_cover, t = s.wall_thickness;
  const double x0 = s.standoff, x1 = s.standoff + s.box_length, yw = 0.5 * s.box_width;
  const double d0 = s.top_depth, d1 = s.top_depth + s.box_height;
  std::vector<Mat> mats;
  for (const auto& [mat, e] : {std::pair<const char*, double>{"out", c}, {"in", t - c}}) {
    const std::array<double, 3> lo{x0 + e, 0.0, d0 + e}, hi{x1 - e, yw - e, d1 - e};
    mats.push_back({fmt::format("front_{}", mat), 0, x0 + e, lo, hi});
    mats.push_back({fmt::format("back_{}", mat), 0, x1 - e, lo, hi});
    mats.push_back({fmt::format("side_{}", mat), 1, yw - e, lo, hi});
    mats.push_back({fmt::format("roof_{}", mat), 2, d0 + e, lo, hi});
    mats.push_back({fmt::format("floor_{}", mat), 2, d1 - e, lo, hi});
  }
  int in_segments = 0, out_segments = 0;  // of the front wall's vertical bars
  b += "# Reinforcement mats as embedded bars (docs/buried-structure.md, \"3-D variant\"): bars named\n"
       "# WALL_MAT_AK, A the bar's direction (x, y or z), K its strip from the symmetry plane or the top.\n";
  for (const Mat& m : mats) {
    for (int along = 0; along < 3; ++along) {
      if (along == m.axis) continue;
      const int across = 3 - m.axis - along;
      const double length = m.hi[along] - m.lo[along], width = m.hi[across] - m.lo[across];
      const int n = strips(width, s.size_structure);
      const int segments = std::max(2, strips(length, s.size_structure));
      const double strip = width / n;
      if (m.name == "front_in" && along == 2) in_segments = segments;
      if (m.name == "front_out" && along == 2) out_segments = segments;
      for (int k = 0; k < n; ++k) {
        std::array<double, 3> from{}, to{};
        from[m.axis] = to[m.axis] = m.at;
        from[across] = to[across] = m.lo[across] + (k + 0.5) * strip;
        from[along] = m.lo[along];
        to[along] = m.hi[along];  // vertical bars run downwards: segment 1 at the top
        fmt::format_to(out,
                       "[[bars]]\nname = \"{}_{}{}\"\nfrom = [{:.9g}, {:.9g}, {:.9g}]\nto = [{:.9g}, {:.9g}, "
                       "{:.9g}]\nsegments = {}\narea = {:.9g}  # m^2\nmaterial = \"steel\"\n\n",
                       m.name, axis_letter(along), k + 1, from[0], from[1], -from[2] + 0.0, to[0], to[1],
                       -to[2] + 0.0, segments, s.rebar_ratio * t * strip);
      }
    }
  }
  // Fig. 13's rebar gauges: the front wall's vertical bars nearest the symmetry plane.
  fmt::format_to(out,
                 "# rebar gauges (bars.csv): In-1=front_in_z1.1 In-2=front_in_z1.{} In-3=front_in_z1.{} "
                 "Out-1=front_out_z1.1 Out-2=front_out_z1.{} Out-3=front_out_z1.{}\n\n",
                 (in_segments + 1) / 2, in_segments, (out_segments + 1) / 2, out_segments);
}

}  // namespace camouflet::buried_detail
