#pragma once
// The state of one material batch for checkpoints (core/state_visitor.hpp):
// every MaterialPoints array and every History column, by name.
#include "core/state_visitor.hpp"
#include "materials/material_points.hpp"

namespace camouflet {

// History columns are matched by name; on loading, a column the checkpoint
// lacks or one of another length is refused (the material models differ).
void visit_state(StateVisitor& visitor, MaterialPoints& points);

}  // namespace camouflet
