#include "interrupt_guard.h"

#include <csignal>

namespace reconfig::cli {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;
struct sigaction g_previous {};

void on_interrupt(int) { g_interrupted = 1; }

}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted = 0;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  action.sa_flags = SA_RESETHAND;  // the second Ctrl+C is the default one: it kills
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous);
}

InterruptGuard::~InterruptGuard() { sigaction(SIGINT, &g_previous, nullptr); }

bool InterruptGuard::interrupted() const { return g_interrupted != 0; }

ProgressCallback InterruptGuard::wrap(ProgressCallback inner) const {
  return [inner = std::move(inner)](double fraction) { return report_progress(inner, fraction) && g_interrupted == 0; };
}

}  // namespace reconfig::cli
