// [[gauges]] groups and [[detonation]] points (docs/case-format.md).
#include <fmt/format.h>

#include <set>

#include "case/sections.hpp"

namespace camouflet::case_detail {

namespace {

// A gauge's or member's name: usable in a CSV header, and not used twice in its group.
std::string unique_name(TomlReader& entry, std::set<std::string>& names, const char* what) {
  std::string name = entry.string("name");
  check_name(entry, "name", name);
  if (!names.insert(name).second) entry.fail("name", fmt::format("{} '{}' appears twice", what, name));
  return name;
}

}  // namespace

void read_gauges(TomlReader& root, Model& model) {
  const int dim = model.dimension();
  std::set<std::string> groups;
  for (auto& g : root.tables("gauges")) {
    GaugeGroup group;
    group.where = g.where();
    group.name = g.string("name");
    check_name(g, "name", group.name);
    if (!groups.insert(group.name).second)
      g.fail("name", fmt::format("gauge group '{}' is defined twice", group.name));
    // Gauges among particles: follow the nearest particle, or interpolate at the fixed point.
    const bool interpolate = g.choice("particles", {"follow", "interpolate"}, "follow") == "interpolate";
    const bool has_points = g.has("points"), has_line = g.has("from") || g.has("to") || g.has("count");
    const bool has_members = g.has("members");
    g.allow({"from", "to", "count"});
    if (int(has_points) + int(has_line) + int(has_members) != 1)
      g.fail(has_points ? (has_line ? "from" : "members") : has_line ? "members" : "points",
             "a gauge group needs exactly one of `points = [{name, position}, ...]`, a line `from`, `to`, "
             "`count`, or `members = [{name, material, min, max}, ...]`");
    if (has_members) {
      auto members = g.tables("members");
      if (members.empty()) g.fail("members", "needs at least one member");
      std::set<std::string> names;
      for (auto& m : members) {
        GaugePoint gauge;
        gauge.name = unique_name(m, names, "member");
        gauge.member = true;
        if (m.has("material")) gauge.member_material = material_index(model, m, "material");
        gauge.region_min = m.vector("min", dim);
        gauge.region_max = m.vector("max", dim);
        for (int i = 0; i < dim; ++i)
          if (!(gauge.region_min[static_cast<std::size_t>(i)] < gauge.region_max[static_cast<std::size_t>(i)]))
            m.fail("max", fmt::format("component {} must exceed min's", i + 1));
        gauge.where = m.where("min");
        m.finish();
        group.points.push_back(std::move(gauge));
      }
    } else if (has_points) {
      auto points = g.tables("points");
      if (points.empty()) g.fail("points", "needs at least one gauge");
      std::set<std::string> names;
      for (auto& p : points) {
        GaugePoint gauge;
        gauge.name = unique_name(p, names, "gauge");
        gauge.position = p.vector("position", dim);
        gauge.where = p.where("position");
        gauge.interpolate = interpolate;
        p.finish();
        group.points.push_back(std::move(gauge));
      }
    } else {
      const auto from = g.vector("from", dim), to = g.vector("to", dim);
      const std::int64_t count = g.integer("count", 0);
      if (count < 1 || count > 10000) g.fail("count", fmt::format("must lie in [1, 10000], got {}", count));
      for (std::int64_t k = 0; k < count; ++k) {
        GaugePoint gauge;
        gauge.name = fmt::format("p{}", k + 1);
        const double w = count > 1 ? static_cast<double>(k) / static_cast<double>(count - 1) : 0.0;
        for (std::size_t i = 0; i < 3; ++i) gauge.position[i] = (1.0 - w) * from[i] + w * to[i];
        gauge.interpolate = interpolate;
        gauge.where = g.where("from");
        gauge.where.key = g.key_path(fmt::format("from/to (gauge {})", gauge.name));
        group.points.push_back(std::move(gauge));
      }
    }
    g.finish();
    model.gauges.push_back(std::move(group));
  }
}

void read_detonations(TomlReader& root, Model& model) {
  const int dim = model.dimension();
  for (auto& d : root.tables("detonation")) {
    DetonationPoint point;
    point.position = d.vector("position", dim);
    point.time = d.non_negative("time", 0.0);
    d.finish();
    model.detonations.push_back(point);
    model.detonation_where.push_back(d.where());
  }
}

}  // namespace camouflet::case_detail
