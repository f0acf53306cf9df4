#pragma once
// Named model parameters as read from a case file (or a preset), each with the
// place it came from. Material and boundary factories take what they need by
// name; `finish()` then refuses any key nobody asked for, suggesting the
// nearest valid one, so a misspelt key is never silently ignored.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace camouflet {

class Parameters {
 public:
  struct Value {
    enum class Kind { number, string, boolean, number_list } kind = Kind::number;
    double number = 0.0;
    std::string text;
    bool flag = false;
    std::vector<double> list;
    SourceLocation where;
  };

  Parameters() = default;
  // `block` is the location of the table itself (used when a required key is missing).
  explicit Parameters(SourceLocation block) : block_(std::move(block)) {}

  void set_number(const std::string& key, double v, SourceLocation where = {});
  void set_string(const std::string& key, std::string v, SourceLocation where = {});
  void set_bool(const std::string& key, bool v, SourceLocation where = {});
  void set_list(const std::string& key, std::vector<double> v, SourceLocation where = {});
  // Values already present win: used to lay a preset under the user's keys.
  void merge_defaults(const Parameters& preset);

  bool has(const std::string& key) const;
  double number(const std::string& key);                  // required
  double number(const std::string& key, double fallback);  // optional
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  bool flag(const std::string& key, bool fallback);
  std::vector<double> list(const std::string& key);

  // Convenience checks that throw InputError naming the key.
  double positive(const std::string& key);
  double positive(const std::string& key, double fallback);
  double non_negative(const std::string& key, double fallback);
  double in_range(const std::string& key, double lo, double hi, double fallback);

  // Where a key was given (or the block itself when absent).
  SourceLocation where(const std::string& key) const;
  const SourceLocation& block() const { return block_; }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  // Throws InputError for the first key that was given but never read.
  void finish() const;

  std::vector<std::string> keys() const;

 private:
  const Value& get(const std::string& key, Value::Kind kind);
  SourceLocation block_;
  std::map<std::string, Value> values_;
  mutable std::set<std::string> used_;
  mutable std::set<std::string> asked_;  // every key a factory looked for: the valid names
};

// Nearest candidate by edit distance, or empty when nothing is close.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace camouflet
