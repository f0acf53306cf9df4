#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace camouflet {

std::string SourceLocation::describe() const {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (line > 0) s += fmt::format(":{}", line);
  if (line > 0 && column > 0) s += fmt::format(":{}", column);
  if (!key.empty()) s += fmt::format(": key '{}'", key);
  return s;
}

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(where.describe() + ": " + message), where_(std::move(where)), message_(message) {}

const char* to_string(EntityKind kind) {
  switch (kind) {
    case EntityKind::element: return "element";
    case EntityKind::particle: return "particle";
    case EntityKind::node: return "node";
    case EntityKind::material_point: return "material point";
    case EntityKind::model: return "model";
  }
  return "entity";
}

std::string NumericalError::compose(EntityKind kind, std::int64_t id, const std::string& quantity,
                                    const std::string& detail) {
  return fmt::format("{} {}: {}: {}", to_string(kind), id, quantity, detail);
}

NumericalError::NumericalError(EntityKind kind, std::int64_t id, std::string quantity, std::string detail)
    : std::runtime_error(compose(kind, id, quantity, detail)),
      kind_(kind),
      id_(id),
      quantity_(std::move(quantity)),
      detail_(std::move(detail)),
      full_(compose(kind_, id_, quantity_, detail_)) {}

void NumericalError::set_context(std::int64_t cycle, double time, const std::string& where) {
  cycle_ = cycle;
  time_ = time;
  full_ = fmt::format("{} {}{}: {} at cycle {}, time {:.6e} s: {}", to_string(kind_), id_,
                      where.empty() ? "" : " (" + where + ")", quantity_, cycle, time, detail_);
  // std::runtime_error's message is fixed at construction; rebuild it.
  static_cast<std::runtime_error&>(*this) = std::runtime_error(full_);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace camouflet
