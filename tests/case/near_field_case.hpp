#pragma once
// The buried-structure case cut down to its near field, shared by
// test_join_near_field.cpp and long_near_field_hourglass.cpp: 100 kg TNT 0.5 m
// deep on the axis of an r-z soil block 2.5 m x 3.5 m (0.05 m cells, the
// `default` resolution), the soil in r <= 1.5 m down to 2 m as SPH particles
// joined to the FEM soil, transmitting far edges.
#include <fmt/format.h>

#include <string>

namespace camouflet::test {

// end_time in s; hourglass_form "" keeps the run-wide default (viscous, 0.1),
// else [run.hourglass] form = hourglass_form, coefficient = 0.1.
inline std::string near_field_case(const std::string& title, double end_time,
                                   const std::string& hourglass_form = "") {
  const std::string hourglass =
      hourglass_form.empty()
          ? ""
          : fmt::format("\n[run.hourglass]\nform = \"{}\"\ncoefficient = 0.1\n", hourglass_form);
  return fmt::format(R"(title = "{}"
[run]
geometry = "axisymmetric"
end_time = {}
cfl = 0.6
{}
[materials.soil]
preset = "sandy_clay_wang2005_seismic"

[materials.charge]
preset = "tnt_wang2005"

[[parts]]
name = "soil"
material = "soil"
block = {{ origin = [0, -3.5], size = [2.5, 3.5], cells = [50, 70] }}

[[parts]]
name = "charge"
kind = "sph"
material = "charge"
fill = {{ shape = "sphere", centre = [0.0, -0.5], radius = 0.244666548, spacing = 0.025 }}

[[parts]]
name = "near_field"
kind = "sph"
material = "soil"
join = true
exclude = ["charge"]
fill = {{ shape = "box", min = [0.0, -2], max = [1.5, 0.0], spacing = 0.05 }}

[sph]
viscosity_alpha = 0.2
viscosity_beta = 2.0

[[boundary]]
type = "axis"
set = "soil.xmin"

[[boundary]]
type = "transmitting"
set = "soil.xmax"

[[boundary]]
type = "transmitting"
set = "soil.ymin"

[[detonation]]
position = [0.0, -0.5]
time = 0.0
)",
                     title, end_time, hourglass);
}

}  // namespace camouflet::test
