#include "cli/signals.h"

#include <signal.h>

#include <array>
#include <csignal>

namespace octopoint::cli {
namespace {

constexpr std::array kSignals = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// The one type a signal handler may store to portably (ARMv5 has no lock-free std::atomic<int>).
volatile std::sig_atomic_t g_pending = 0;
std::array<struct sigaction, kSignals.size()> g_previous{};
int g_holders = 0;  // nested holders install and restore once

extern "C" void recordSignal(int signal_number) {
  if (g_pending == 0) g_pending = signal_number;  // the first one decides how the process ends
}

}  // namespace

TerminationSignalsHeld::TerminationSignalsHeld() {
  if (g_holders++ > 0) return;
  g_pending = 0;
  struct sigaction action {};
  action.sa_handler = recordSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // interrupted reads and writes resume instead of failing
  for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &action, &g_previous[i]);
}

TerminationSignalsHeld::~TerminationSignalsHeld() {
  if (--g_holders > 0) return;
  for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
  const int pending = g_pending;
  g_pending = 0;
  if (pending != 0) raise(pending);
}

int TerminationSignalsHeld::interrupted() { return g_pending; }

}  // namespace octopoint::cli
