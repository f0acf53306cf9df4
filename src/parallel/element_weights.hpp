#pragma once
// What an element costs a rank, for METIS to balance (docs/parallel.md): a step of an element of
// concrete takes several times that of an elastic one, so equal element counts would leave the
// rank with the structure waiting for the others every cycle.
#include <vector>

#include "materials/material.hpp"
#include "model/model.hpp"

namespace camouflet {

// A cycle of one element of `material` over one of an elastic one (whole cycle: kinematics,
// forces, material update), from the models' types. Measured with `bench/grind_time --preset`
// (docs/performance.md); a model the table does not name counts as elastic.
double relative_cost(const Material& material);

// One METIS weight per element of the model's mesh: ten times its material's relative cost,
// rounded (whole numbers >= 1, as METIS takes them).
std::vector<int> element_weights(const Model& model);

}  // namespace camouflet
