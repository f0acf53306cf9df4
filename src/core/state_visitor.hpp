#pragma once
// The run's state as a list of named arrays (checkpoints): every
// class that holds state a restart needs offers `visit_state(StateVisitor&)`
// and names each of its arrays and scalars there. A checkpoint writer copies
// them out; a reader fills them back in, resizing first. Adding new state
// (coupling, rebar, erosion) is one more line in the owner's visit_state; the
// restart-determinism tests fail when something is forgotten.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/sym_tensor.hpp"
#include "core/vec.hpp"

namespace camouflet {

enum class StateType : int { f64 = 0, i32 = 1, i64 = 2, u32 = 3, u64 = 4, u8 = 5 };

std::size_t state_type_size(StateType t);

class StateVisitor {
 public:
  virtual ~StateVisitor() = default;
  // True when the visitor writes into the arrays (restoring a checkpoint).
  virtual bool loading() const = 0;
  // `count` entries of `width` values of `type` at `data`. A loading visitor
  // calls resize(count_in_checkpoint), which returns the storage to fill.
  virtual void array(const std::string& name, StateType type, std::size_t width, std::size_t count,
                     const void* data, const std::function<void*(std::size_t)>& resize) = 0;

  // Names are prefixed by the enclosing scopes ("solver.sph.position").
  void push(const std::string& scope) { prefix_.push_back(scope); }
  void pop() { prefix_.pop_back(); }
  std::string qualified(const std::string& name) const {
    std::string s;
    for (const auto& p : prefix_) s += p + ".";
    return s + name;
  }

 private:
  std::vector<std::string> prefix_;
};

class StateScope {
 public:
  StateScope(StateVisitor& v, const std::string& scope) : v_(v) { v_.push(scope); }
  ~StateScope() { v_.pop(); }
  StateScope(const StateScope&) = delete;
  StateScope& operator=(const StateScope&) = delete;

 private:
  StateVisitor& v_;
};

namespace state_detail {
// Element type and width of T as stored: plain doubles for the tensor and vector types.
template <class T>
struct Layout;
template <>
struct Layout<double> {
  static constexpr StateType type = StateType::f64;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<int> {
  static constexpr StateType type = StateType::i32;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<long> {
  static constexpr StateType type = sizeof(long) == 8 ? StateType::i64 : StateType::i32;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<long long> {
  static constexpr StateType type = StateType::i64;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<unsigned int> {
  static constexpr StateType type = StateType::u32;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<unsigned long> {
  static constexpr StateType type = sizeof(unsigned long) == 8 ? StateType::u64 : StateType::u32;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<unsigned char> {
  static constexpr StateType type = StateType::u8;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<char> {
  static constexpr StateType type = StateType::u8;
  static constexpr std::size_t width = 1;
};
template <>
struct Layout<SymTensor> {
  static_assert(sizeof(SymTensor) == 6 * sizeof(double));
  static constexpr StateType type = StateType::f64;
  static constexpr std::size_t width = 6;
};
template <>
struct Layout<Spin> {
  static_assert(sizeof(Spin) == 3 * sizeof(double));
  static constexpr StateType type = StateType::f64;
  static constexpr std::size_t width = 3;
};
template <int D>
struct Layout<Vec<D>> {
  static_assert(sizeof(Vec<D>) == D * sizeof(double));
  static constexpr StateType type = StateType::f64;
  static constexpr std::size_t width = D;
};
}  // namespace state_detail

template <class T>
void visit(StateVisitor& v, const std::string& name, std::vector<T>& a) {
  using L = state_detail::Layout<T>;
  v.array(v.qualified(name), L::type, L::width, a.size(), a.data(), [&a](std::size_t n) -> void* {
    a.resize(n);
    return a.data();
  });
}

// A scalar is an array of one entry; a checkpoint with another count is refused by the reader.
template <class T>
void visit(StateVisitor& v, const std::string& name, T& x) requires std::is_arithmetic_v<T> {
  using L = state_detail::Layout<T>;
  v.array(v.qualified(name), L::type, L::width, 1, &x, [&x, &v, name](std::size_t n) -> void* {
    if (n != 1) throw std::runtime_error("checkpoint: '" + v.qualified(name) + "' is not a scalar");
    return &x;
  });
}

inline void visit(StateVisitor& v, const std::string& name, std::string& s) {
  v.array(v.qualified(name), StateType::u8, 1, s.size(), s.data(), [&s](std::size_t n) -> void* {
    s.resize(n);
    return s.data();
  });
}

}  // namespace camouflet
