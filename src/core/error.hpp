#pragma once
// The two ways a run ends early, each with its exit code (docs/exit-codes.md):
// bad input (2) names file, line and key; a numerical failure (1) names the
// element or particle, the cycle, the time and the quantity that failed.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace camouflet {

enum ExitCode : int {
  exit_ok = 0,
  exit_numerical_failure = 1,
  exit_bad_input = 2,
  exit_io_failure = 3,
  exit_interrupted = 130,
};

// Where a value came from in the user's input.
struct SourceLocation {
  std::string file;
  int line = 0;  // 1-based; 0 when unknown
  int column = 0;
  std::string key;  // dotted path, e.g. "materials.soil.eos.density"

  std::string describe() const;  // "case.toml:12:3: key 'materials.soil.eos.density'"
};

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

// What kind of entity failed.
enum class EntityKind { element, particle, node, material_point, model };

class NumericalError : public std::runtime_error {
 public:
  NumericalError(EntityKind kind, std::int64_t id, std::string quantity, std::string detail);
  EntityKind kind() const { return kind_; }
  std::int64_t id() const { return id_; }
  const std::string& quantity() const { return quantity_; }
  const std::string& detail() const { return detail_; }
  // Cycle and time are filled in by the solver when it catches the error.
  void set_context(std::int64_t cycle, double time, const std::string& where);
  std::int64_t cycle() const { return cycle_; }
  double time() const { return time_; }

 private:
  static std::string compose(EntityKind, std::int64_t, const std::string&, const std::string&);
  EntityKind kind_;
  std::int64_t id_;
  std::string quantity_;
  std::string detail_;
  std::int64_t cycle_ = -1;
  double time_ = 0.0;
  std::string full_;
};

const char* to_string(EntityKind kind);

// Edit distance, for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace camouflet
