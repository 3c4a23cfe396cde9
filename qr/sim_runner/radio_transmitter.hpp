// The pilot's radio in the simulator: sticks and two switches in, CRSF frames out on the board's
// receiver line as a receiver hands them to the flight computer, RC channels at 150 Hz and link
// statistics with every 15th (10 Hz). The channels are the default map (docs/drivers.md section 3,
// AETR: roll 1, pitch 2, lift 3, yaw 4, arm 5, mode 6).
//
// Both simulated pilots fly through it: the scenario pilot (pilot.hpp) sets its sticks and
// switches; in serve mode (serve_radio.hpp) the console's control frames are its sticks and the
// side channel moves its switches.
#pragma once

#include <stdint.h>

#include <common/drivers/crsf.hpp>
#include <common/messages.hpp>
#include <common/mode.hpp>
#include <qr/boards/sim/sim_board.hpp>

namespace qrsim {

// The channels a transmitter sends for these sticks and switches: the mode switch at its position
// (low, centre or high; the mode table's column says which mode each arms, wire::mode_at_switch).
drivers::CrsfChannels transmitter_channels(const wire::Control& sticks, bool arm_switch_on,
                                           wire::ModeSwitch mode_switch);

class RadioTransmitter {
 public:
  // The switch stays off this long before it goes on: a receiver frame or more sees it off.
  static constexpr uint64_t kArmSwitchOffUs = 50000;

  void set_sticks(const wire::Control& sticks) { sticks_ = sticks; }
  const wire::Control& sticks() const { return sticks_; }
  // The mode switch to `mode`'s position and the arm switch off, then on kArmSwitchOffUs later:
  // one movement, one arming attempt (docs/safety.md rule 17). False, and nothing moves, for a
  // mode the radio does not arm (wire::armed_by_the_radio: no position of the switch is its).
  bool arm(wire::Mode mode, uint64_t now_us);
  // The arm switch off; in a flight mode that is the emergency stop of rule 17.
  void disarm() { arming_ = false; }
  bool arm_switch_on(uint64_t now_us) const { return arming_ && now_us >= arm_at_us_; }
  wire::Mode mode_switch() const { return mode_; }

  // Once per control period: an RC frame when one is due, unless `silent` (out of range,
  // switched off); the 150 Hz clock runs on while silent.
  void step(uint64_t now_us, bool silent, SimBoard& board);
  uint32_t rc_frames() const { return rc_frames_; }

 private:
  wire::Control sticks_;
  bool arming_ = false;
  uint64_t arm_at_us_ = 0;
  wire::Mode mode_ = wire::Mode::manual;
  uint64_t next_rc_ns_ = 0;
  uint32_t rc_frames_ = 0;
};

}  // namespace qrsim
