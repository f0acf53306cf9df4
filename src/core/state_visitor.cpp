#include "core/state_visitor.hpp"

namespace camouflet {

std::size_t state_type_size(StateType t) {
  switch (t) {
    case StateType::f64:
    case StateType::i64:
    case StateType::u64:
      return 8;
    case StateType::i32:
    case StateType::u32:
      return 4;
    case StateType::u8:
      return 1;
  }
  return 0;
}

}  // namespace camouflet
