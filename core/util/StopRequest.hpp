#pragma once
// A stop asked for from outside: SIGTERM (a scheduler's warning before it kills, `scancel`,
// `kill`) or SIGINT (Ctrl-C). The handler only sets a flag; long loops poll it between steps,
// write their checkpoint and unwind with Interrupted. A second signal of the same kind takes
// the default action (the process ends at once), so a stuck run can still be stopped.
namespace vorodg {

/// Installs the handlers (idempotent).
void install_stop_handlers();
/// Whether a stop was asked for.
bool stop_requested();
/// The signal that asked (0: none).
int stop_signal();
/// Asks for a stop as a signal would (tests, and a worker that must end its peers).
void request_stop(int signal);
/// Forgets a request (tests).
void clear_stop_request();

}  // namespace vorodg
