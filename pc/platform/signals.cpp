#include <pc/platform/signals.hpp>

#include <signal.h>

#include <initializer_list>

namespace qrterm {
namespace {

volatile sig_atomic_t g_exit_signals = 0;

extern "C" void on_exit_signal(int) { g_exit_signals = g_exit_signals + 1; }

}  // namespace

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_exit_signal;
  sigemptyset(&action.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &action, nullptr);
  signal(SIGPIPE, SIG_IGN);
}

int exit_signals() { return g_exit_signals; }

}  // namespace qrterm
