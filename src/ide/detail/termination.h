#pragma once
// The IDE asked to end by a signal (SIGTERM from a launcher or a session's logout, SIGINT from
// the terminal, SIGHUP when it closes): the handler only notes it; the frame loop, the run's
// steps and a running script look at the note and stop, and the process then ends by that
// signal, saving nothing (the model, its autosave and the settings stay as they were).

#include <atomic>

namespace gdpn::ide {

/// Catches SIGTERM, SIGINT and SIGHUP, even where the process started with them ignored or
/// blocked (a launcher's leftovers): from then on each only sets terminationFlag() and asks a
/// running script to stop.
void catchTermination();
/// True once a signal asked the IDE to end (safe to read from anywhere).
[[nodiscard]] const std::atomic<bool>& terminationFlag();
/// Ends the process by the signal that asked, with its default action, so that the parent sees
/// it ended by that signal (a shell says 128 + its number: 143 for SIGTERM). Writes nothing.
[[noreturn]] void endByTermination();

}  // namespace gdpn::ide
