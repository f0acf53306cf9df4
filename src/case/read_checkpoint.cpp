// [checkpoint]: when a run writes its restart files (docs/case-format.md, docs/reliability.md).
#include <fmt/format.h>

#include "case/sections.hpp"

namespace camouflet::case_detail {

void read_checkpoint(TomlReader& r, Model& model) {
  CheckpointControl& c = model.checkpoint;
  if (r.has("interval_cycles")) {
    c.interval_cycles = r.integer("interval_cycles", 0);
    if (c.interval_cycles < 1)
      r.fail("interval_cycles", fmt::format("must be at least 1, got {}", c.interval_cycles));
  }
  if (r.has("interval_wall_s")) c.interval_wall_s = r.positive("interval_wall_s");
  if (r.has("keep")) {
    const std::int64_t keep = r.integer("keep", c.keep);
    if (keep < 1 || keep > 1000) r.fail("keep", fmt::format("must lie in 1 .. 1000, got {}", keep));
    c.keep = static_cast<int>(keep);
  }
  if (!c.enabled())
    r.fail("interval_cycles", "a [checkpoint] block needs interval_cycles or interval_wall_s");
  r.finish();
}

}  // namespace camouflet::case_detail
