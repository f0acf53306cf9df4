#include "case/toml_reader.hpp"

#include <fmt/format.h>

#include <cmath>

namespace camouflet {

SourceLocation location_of(const toml::node& node, const std::string& file, const std::string& key) {
  SourceLocation w;
  w.file = file;
  w.line = static_cast<int>(node.source().begin.line);
  w.column = static_cast<int>(node.source().begin.column);
  w.key = key;
  return w;
}

std::optional<double> as_number(const toml::node& node) {
  if (node.is_floating_point()) return node.as_floating_point()->get();
  if (node.is_integer()) return static_cast<double>(node.as_integer()->get());
  return std::nullopt;
}

TomlReader::TomlReader(const toml::table& table, std::string file, std::string path)
    : table_(table), file_(std::move(file)), path_(std::move(path)) {}

std::string TomlReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

SourceLocation TomlReader::where() const {
  return location_of(table_, file_, path_);
}

SourceLocation TomlReader::where(const std::string& key) const {
  if (const toml::node* n = table_.get(key)) return location_of(*n, file_, key_path(key));
  SourceLocation w = where();
  w.key = key_path(key);
  return w;
}

void TomlReader::fail(const std::string& key, const std::string& message) const {
  throw InputError(where(key), message);
}

void TomlReader::missing(const std::string& key) const {
  // A required key that is absent is most often misspelt: point at the typo.
  for (const auto& [name, value] : table_) {
    const std::string k(name.str());
    if (used_.count(k) || known_.count(k)) continue;
    if (nearest(k, {key}) == key)
      throw InputError(location_of(value, file_, key_path(k)),
                       fmt::format("unknown key; did you mean '{}'?", key));
  }
  fail(key, "required key is missing");
}

void TomlReader::allow(std::initializer_list<const char*> keys) {
  for (const char* k : keys) known_.insert(k);
}

bool TomlReader::has(const std::string& key) {
  known_.insert(key);
  return table_.contains(key);
}

const toml::node* TomlReader::node(const std::string& key) {
  known_.insert(key);
  const toml::node* n = table_.get(key);
  if (n) used_.insert(key);
  return n;
}

double TomlReader::number(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) missing(key);
  const auto v = as_number(*n);
  if (!v) fail(key, "expected a number");
  if (!std::isfinite(*v)) fail(key, "must be a finite number");
  return *v;
}

double TomlReader::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : fallback;
}

double TomlReader::positive(const std::string& key) {
  const double v = number(key);
  if (!(v > 0.0)) fail(key, fmt::format("must be positive, got {}", v));
  return v;
}

double TomlReader::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : fallback;
}

double TomlReader::non_negative(const std::string& key, double fallback) {
  const double v = number(key, fallback);
  if (!(v >= 0.0)) fail(key, fmt::format("must not be negative, got {}", v));
  return v;
}

std::int64_t TomlReader::integer(const std::string& key, std::int64_t fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (!n->is_integer()) fail(key, "expected an integer");
  return n->as_integer()->get();
}

std::string TomlReader::string(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) missing(key);
  if (!n->is_string()) fail(key, "expected a string");
  return n->as_string()->get();
}

std::string TomlReader::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

std::string TomlReader::choice(const std::string& key, const std::vector<std::string>& choices,
                               const std::string& fallback) {
  const std::string v = fallback.empty() ? string(key) : string(key, fallback);
  for (const auto& c : choices)
    if (v == c) return v;
  const std::string guess = nearest(v, choices);
  fail(key, guess.empty() ? fmt::format("'{}' is not one of: {}", v, fmt::join(choices, ", "))
                          : fmt::format("'{}' is not one of: {}; did you mean '{}'?", v,
                                        fmt::join(choices, ", "), guess));
}

std::vector<double> TomlReader::numbers(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) missing(key);
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected a list of numbers");
  std::vector<double> out;
  for (const auto& item : *a) {
    const auto v = as_number(item);
    if (!v) fail(key, "expected a list of numbers");
    if (!std::isfinite(*v)) fail(key, "must contain finite numbers");
    out.push_back(*v);
  }
  return out;
}

std::array<double, 3> TomlReader::vector(const std::string& key, int dim) {
  const auto v = numbers(key);
  if (static_cast<int>(v.size()) != dim)
    fail(key, fmt::format("expected {} components for a {}-D model, got {}", dim, dim, v.size()));
  std::array<double, 3> out{};
  for (int i = 0; i < dim; ++i) out[static_cast<std::size_t>(i)] = v[static_cast<std::size_t>(i)];
  return out;
}

std::array<double, 3> TomlReader::vector(const std::string& key, int dim,
                                         const std::array<double, 3>& fallback) {
  return has(key) ? vector(key, dim) : fallback;
}

std::optional<TomlReader> TomlReader::table(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::table* t = n->as_table();
  if (!t) fail(key, "expected a table");
  return TomlReader(*t, file_, key_path(key));
}

std::vector<TomlReader> TomlReader::tables(const std::string& key) {
  std::vector<TomlReader> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(key, fmt::format("expected an array of tables ([[{}]])", key));
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = (*a)[i].as_table();
    const std::string p = fmt::format("{}[{}]", key_path(key), i);
    if (!t) throw InputError(location_of((*a)[i], file_, p), "expected a table");
    out.emplace_back(*t, file_, p);
  }
  return out;
}

const toml::array* TomlReader::array(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return nullptr;
  if (!n->is_array()) fail(key, "expected a list");
  return n->as_array();
}

std::vector<std::string> TomlReader::keys() const {
  std::vector<std::string> k;
  for (const auto& [name, value] : table_) k.emplace_back(name.str());
  return k;
}

void TomlReader::finish() const {
  const std::vector<std::string> valid(known_.begin(), known_.end());
  for (const auto& [name, value] : table_) {
    const std::string k(name.str());
    if (used_.count(k)) continue;
    const std::string guess = nearest(k, valid);
    throw InputError(location_of(value, file_, key_path(k)),
                     guess.empty() ? fmt::format("unknown key; valid keys here: {}", fmt::join(valid, ", "))
                                   : fmt::format("unknown key; did you mean '{}'?", guess));
  }
}

Parameters TomlReader::parameters() {
  Parameters p(where());
  for (const auto& [name, value] : table_) {
    const std::string k(name.str());
    used_.insert(k);
    const SourceLocation w = location_of(value, file_, key_path(k));
    if (const auto v = as_number(value)) {
      if (!std::isfinite(*v)) throw InputError(w, "must be a finite number");
      p.set_number(k, *v, w);
    } else if (value.is_string()) {
      p.set_string(k, value.as_string()->get(), w);
    } else if (value.is_boolean()) {
      p.set_bool(k, value.as_boolean()->get(), w);
    } else if (const toml::array* a = value.as_array()) {
      std::vector<double> list;
      for (const auto& item : *a) {
        const auto v = as_number(item);
        if (!v) throw InputError(w, "expected a number, a string, true/false or a list of numbers");
        if (!std::isfinite(*v)) throw InputError(w, "must contain finite numbers");
        list.push_back(*v);
      }
      p.set_list(k, std::move(list), w);
    } else {
      throw InputError(w, "expected a number, a string, true/false or a list of numbers");
    }
  }
  return p;
}

}  // namespace camouflet
