// Signals that end the IDE: noted by the handler, acted on between frames.

#include "termination.h"

#include <signal.h>
#include <unistd.h>

#include <cstdlib>

#include "gdpn/script/engine.h"

namespace gdpn::ide {

namespace {

std::atomic<bool> g_terminate{false};
volatile sig_atomic_t g_signal = 0;

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};

void onTermination(int sig) {
  if (g_signal == 0) g_signal = sig;
  g_terminate.store(true);
  script::requestInterrupt();  // a script running now stops (its call returns soon)
}

}  // namespace

void catchTermination() {
  sigset_t set;
  sigemptyset(&set);
  for (const int sig : kSignals) {
    struct sigaction on{};
    on.sa_handler = onTermination;
    sigemptyset(&on.sa_mask);
    on.sa_flags = SA_RESTART;
    ::sigaction(sig, &on, nullptr);
    sigaddset(&set, sig);
  }
  // a launcher may have blocked them too: a blocked signal would wait for ever
  ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

const std::atomic<bool>& terminationFlag() { return g_terminate; }

void endByTermination() {
  const int sig = g_signal != 0 ? static_cast<int>(g_signal) : SIGTERM;
  struct sigaction dfl{};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
  ::_exit(128 + sig);  // not reached: the default action of these signals ends the process
}

}  // namespace gdpn::ide
