// Serve mode with a radio (qrsim --serve --rc crsf): the pilot at the console flies through the
// radio, as a pilot holds a transmitter beside the laptop. The console's control frames (the QR
// reads them too, and ignores them while the radio flies: docs/safety.md rule 17) are the
// transmitter's sticks, and the side channel's `radio arm MODE` and `radio off` move its switches
// (qrterm's flight-mode keys and its `m` key, docs/console.md).
//
// When the console's control frames stop for kSticksLostUs the transmitter goes silent (nobody
// holds the sticks any more): the QR sees the radio's link lost, the panic of rule 7.
#pragma once

#include <stdint.h>

#include <common/frame_parser.hpp>
#include <qr/boards/sim/sim_board.hpp>
#include <qr/sim_runner/radio_transmitter.hpp>

namespace qrsim {

class ServeRadio {
 public:
  // Five of the console's 50 Hz control frames missing.
  static constexpr uint64_t kSticksLostUs = 100000;

  // A byte the console sent the QR, as it goes onto the line.
  void hear(uint8_t byte, uint64_t now_us);
  // Once per control period.
  void step(uint64_t now_us, SimBoard& board);
  // True while the console's sticks are fresh enough to fly by.
  bool sending(uint64_t now_us) const { return heard_ && now_us - sticks_at_us_ < kSticksLostUs; }

  RadioTransmitter& transmitter() { return transmitter_; }

 private:
  wire::FrameParser parser_{wire::Listen::pc_to_qr};
  RadioTransmitter transmitter_;
  bool heard_ = false;
  uint64_t sticks_at_us_ = 0;
};

}  // namespace qrsim
