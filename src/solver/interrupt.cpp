#include "solver/interrupt.hpp"

#include <csignal>

namespace camouflet {

namespace {
volatile std::sig_atomic_t stop_signal = 0;
}

void request_stop(int signal) noexcept {
  stop_signal = signal;
}
int stop_requested() noexcept {
  return stop_signal;
}
void clear_stop_request() noexcept {
  stop_signal = 0;
}

}  // namespace camouflet
