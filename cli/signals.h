#pragma once
// Holding termination signals (SIGINT, SIGTERM, SIGHUP, SIGQUIT) while a tool puts its output in
// place, so that Ctrl-C or a kill never leaves a half-renamed set of files or a staging folder.
// While a TerminationSignalsHeld lives, such a signal is only recorded (in whichever thread it
// lands: a handler, not a signal mask, because libraries keep their own threads); the writer asks
// interrupted() between steps and cleans up. When the last holder goes, the earlier handlers come
// back and a recorded signal is raised again, so the process ends as the signal asked, with
// nothing left behind.

namespace octopoint::cli {

class TerminationSignalsHeld {
 public:
  TerminationSignalsHeld();
  ~TerminationSignalsHeld();
  TerminationSignalsHeld(const TerminationSignalsHeld&) = delete;
  TerminationSignalsHeld& operator=(const TerminationSignalsHeld&) = delete;

  // The signal that came while held, or 0.
  static int interrupted();
};

}  // namespace octopoint::cli
