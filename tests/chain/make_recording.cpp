// Writes the synthetic flight (synthetic_flight.hpp) as a replay input CSV (docs/replay.md):
//   make-recording [--hz 1000|500] > tests/data/synthetic_flight.csv
// The committed recording is its output at 1 kHz; Replay.CommittedRecordingIsTheGeneratorsOutput
// compares them, so the file cannot drift from its generator.
#include <cstdio>
#include <cstring>

#include "recording.hpp"

int main(int argc, char** argv) {
  const bool at_500 = argc == 3 && std::strcmp(argv[1], "--hz") == 0 && std::strcmp(argv[2], "500") == 0;
  const bool at_1000 = argc == 1 ||
                       (argc == 3 && std::strcmp(argv[1], "--hz") == 0 && std::strcmp(argv[2], "1000") == 0);
  if (!at_500 && !at_1000) {
    std::fprintf(stderr, "usage: make-recording [--hz 1000|500]\n");
    return 2;
  }
  const std::string csv = at_500 ? qr::chain::test::synthetic_recording_csv<500>()
                                 : qr::chain::test::synthetic_recording_csv<1000>();
  std::fputs(csv.c_str(), stdout);
  return 0;
}
