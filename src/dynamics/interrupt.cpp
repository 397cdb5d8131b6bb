#include "dynamics/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace hmfnet {
namespace {

// Lock-free, so reading and writing it from a signal handler is defined behaviour.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_interrupt(int signal) {
  g_signal.store(signal, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the process at once
}

}  // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

int interrupt_signal() { return g_signal.load(std::memory_order_relaxed); }

void set_interrupt_signal(int signal) { g_signal.store(signal, std::memory_order_relaxed); }

}  // namespace hmfnet
