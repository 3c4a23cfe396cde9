// The soak (docs/simulator.md section 9): the host firmware flies full control for an hour of
// simulated time, headless, flown by a scripted pilot over a damaged line (5 % of the bytes lost
// each way, a burst of garbage up the line every few seconds, the line silent for less than the
// link timeout every few seconds), logging all the while, and downloads its log at the end. A
// referee beside the line judges every mode change the firmware makes and every gap in what it
// received: a link-loss panic must come exactly when no valid frame reached the QR for the link
// timeout, and no other change may come that the pilot did not ask for.
#pragma once

#include <stdint.h>

#include <string>

namespace qrsim {

struct SoakOptions {
  double seconds = 3600;  // of flight, from the first take-off; the download comes after
  uint64_t seed = 1;
  double byte_loss = 0.05;
  double garbage_every_s = 3;
  double outage_every_s = 5;
  double outage_s = 0.1;  // shorter than the link timeout (default 250 ms)
};

// Flies the soak and prints its figures as one JSON line, {"soak": ...}. True when it passed:
// no deadline miss, no unexplained mode change, no link loss unanswered, every log line the
// firmware wrote downloaded whole and none missing between them.
bool run_soak(const SoakOptions& options);

}  // namespace qrsim
