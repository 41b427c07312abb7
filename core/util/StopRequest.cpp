#include "core/util/StopRequest.hpp"

#include <atomic>
#include <csignal>

namespace vorodg {
namespace {

std::atomic<int> requested{0};
static_assert(std::atomic<int>::is_always_lock_free, "the handler needs a lock-free flag");

extern "C" void on_stop_signal(int signal) {
  requested.store(signal, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);  // the next one ends the process
}

}  // namespace

void install_stop_handlers() {
  for (int s : {SIGTERM, SIGINT}) std::signal(s, on_stop_signal);
}

bool stop_requested() {
  return requested.load(std::memory_order_relaxed) != 0;
}

int stop_signal() {
  return requested.load(std::memory_order_relaxed);
}

void request_stop(int signal) {
  requested.store(signal, std::memory_order_relaxed);
}

void clear_stop_request() {
  requested.store(0, std::memory_order_relaxed);
}

}  // namespace vorodg
