#pragma once
// A TOML table as the case reader sees it: typed getters that turn every
// problem into an InputError naming file, line and the dotted key, and a
// finish() that refuses any key nobody asked for, suggesting the nearest
// valid one. Every section reader works through this class, so no
// key of the case file is ever silently ignored.
#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/parameters.hpp"

namespace camouflet {

class TomlReader {
 public:
  // `path` is the dotted key of the table itself ("" for the root).
  TomlReader(const toml::table& table, std::string file, std::string path);

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string key_path(const std::string& key) const;
  SourceLocation where() const;                        // the table
  SourceLocation where(const std::string& key) const;  // the key (the table when absent)
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  // Declares a key valid without reading it (for finish()'s suggestions).
  void allow(std::initializer_list<const char*> keys);
  bool has(const std::string& key);
  const toml::node* node(const std::string& key);

  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  double positive(const std::string& key);
  double positive(const std::string& key, double fallback);
  double non_negative(const std::string& key, double fallback);
  std::int64_t integer(const std::string& key, std::int64_t fallback);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  // One of `choices`; "did you mean" on anything else.
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& fallback);
  // A position-like list of `dim` numbers (2-D accepts [x, y]).
  std::array<double, 3> vector(const std::string& key, int dim);
  std::array<double, 3> vector(const std::string& key, int dim, const std::array<double, 3>& fallback);
  std::vector<double> numbers(const std::string& key);

  // Sub-tables and arrays of tables (array element paths are "key[i]").
  std::optional<TomlReader> table(const std::string& key);
  std::vector<TomlReader> tables(const std::string& key);
  const toml::array* array(const std::string& key);

  // The table's keys that were never asked for: InputError on the first.
  void finish() const;
  std::vector<std::string> keys() const;

  // A whole table as model Parameters (numbers, strings, booleans, lists of
  // numbers), each value with its location; used for material blocks.
  Parameters parameters();

 private:
  [[noreturn]] void missing(const std::string& key) const;
  const toml::table& table_;
  std::string file_;
  std::string path_;
  std::set<std::string> used_;
  std::set<std::string> known_;
};

// Location of any node of the document.
SourceLocation location_of(const toml::node& node, const std::string& file, const std::string& key);

// A number from a node (integer or float), or nothing.
std::optional<double> as_number(const toml::node& node);

}  // namespace camouflet
