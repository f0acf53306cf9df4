#include "core/parameters.hpp"

#include <fmt/format.h>

namespace camouflet {

namespace {
const char* kind_name(Parameters::Value::Kind k) {
  switch (k) {
    case Parameters::Value::Kind::number: return "a number";
    case Parameters::Value::Kind::string: return "a string";
    case Parameters::Value::Kind::boolean: return "true or false";
    case Parameters::Value::Kind::number_list: return "a list of numbers";
  }
  return "a value";
}
}  // namespace

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  // Close enough to be a typo: at most a third of the word, and at least 2 edits allowed.
  if (best_d <= std::max<std::size_t>(2, word.size() / 3)) return best;
  return {};
}

void Parameters::set_number(const std::string& key, double v, SourceLocation where) {
  Value val;
  val.kind = Value::Kind::number;
  val.number = v;
  val.where = std::move(where);
  values_[key] = std::move(val);
}
void Parameters::set_string(const std::string& key, std::string v, SourceLocation where) {
  Value val;
  val.kind = Value::Kind::string;
  val.text = std::move(v);
  val.where = std::move(where);
  values_[key] = std::move(val);
}
void Parameters::set_bool(const std::string& key, bool v, SourceLocation where) {
  Value val;
  val.kind = Value::Kind::boolean;
  val.flag = v;
  val.where = std::move(where);
  values_[key] = std::move(val);
}
void Parameters::set_list(const std::string& key, std::vector<double> v, SourceLocation where) {
  Value val;
  val.kind = Value::Kind::number_list;
  val.list = std::move(v);
  val.where = std::move(where);
  values_[key] = std::move(val);
}

void Parameters::merge_defaults(const Parameters& preset) {
  for (const auto& [k, v] : preset.values_)
    if (!values_.count(k)) values_[k] = v;
}

bool Parameters::has(const std::string& key) const {
  asked_.insert(key);
  return values_.count(key) != 0;
}

SourceLocation Parameters::where(const std::string& key) const {
  auto it = values_.find(key);
  if (it != values_.end() && (it->second.where.line > 0 || !it->second.where.file.empty())) return it->second.where;
  SourceLocation w = block_;
  w.key = block_.key.empty() ? key : block_.key + "." + key;
  return w;
}

void Parameters::fail(const std::string& key, const std::string& message) const {
  throw InputError(where(key), message);
}

const Parameters::Value& Parameters::get(const std::string& key, Value::Kind kind) {
  asked_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end()) {
    // A required parameter that is absent is most often misspelt: point at the typo.
    for (const auto& [k, v] : values_)
      if (!used_.count(k) && !asked_.count(k) && nearest(k, {key}) == key)
        fail(k, fmt::format("unknown parameter; did you mean '{}'?", key));
    fail(key, "required parameter is missing");
  }
  used_.insert(key);
  if (it->second.kind != kind) {
    // An integer list or a single number where a list is wanted is fine.
    if (kind == Value::Kind::number_list && it->second.kind == Value::Kind::number) {
      it->second.kind = Value::Kind::number_list;
      it->second.list = {it->second.number};
    } else {
      fail(key, fmt::format("expected {}", kind_name(kind)));
    }
  }
  return it->second;
}

double Parameters::number(const std::string& key) { return get(key, Value::Kind::number).number; }
double Parameters::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : fallback;
}
std::string Parameters::string(const std::string& key) { return get(key, Value::Kind::string).text; }
std::string Parameters::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}
bool Parameters::flag(const std::string& key, bool fallback) {
  return has(key) ? get(key, Value::Kind::boolean).flag : fallback;
}
std::vector<double> Parameters::list(const std::string& key) { return get(key, Value::Kind::number_list).list; }

double Parameters::positive(const std::string& key) {
  const double v = number(key);
  if (!(v > 0.0)) fail(key, fmt::format("must be positive, got {}", v));
  return v;
}
double Parameters::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : fallback;
}
double Parameters::non_negative(const std::string& key, double fallback) {
  const double v = number(key, fallback);
  if (!(v >= 0.0)) fail(key, fmt::format("must not be negative, got {}", v));
  return v;
}
double Parameters::in_range(const std::string& key, double lo, double hi, double fallback) {
  const double v = number(key, fallback);
  if (!(v >= lo && v <= hi)) fail(key, fmt::format("must lie in [{}, {}], got {}", lo, hi, v));
  return v;
}

std::vector<std::string> Parameters::keys() const {
  std::vector<std::string> k;
  for (const auto& [name, v] : values_) k.push_back(name);
  return k;
}

void Parameters::finish() const {
  std::vector<std::string> valid(asked_.begin(), asked_.end());
  for (const auto& [k, v] : values_) {
    if (used_.count(k)) continue;
    const std::string guess = nearest(k, valid);
    fail(k, guess.empty() ? "unknown parameter" : fmt::format("unknown parameter; did you mean '{}'?", guess));
  }
}

}  // namespace camouflet
