// SIGINT, SIGTERM and SIGHUP do not kill the console on the spot: they are counted, and the main
// loop turns the first into the ordinary exit (QR to safe, terminal restored, files saved) and a
// second into an exit without waiting for the QR. SIGPIPE is ignored: a vanished reader is an
// error return, handled where it happens.
#pragma once

namespace qrterm {

void install_signal_handlers();
int exit_signals();  // how many have arrived

}  // namespace qrterm
