// A DShot ESC's spin direction, set and saved on the bench: the motor test found an engine turning
// the wrong way, and its ESC is told so rather than two of the motor's wires swapped. DShot's "spin
// direction 1" (the ESC's normal) or "spin direction 2" (reversed), then "save settings", both to
// that engine alone; each is a setting, which the board's sequencer sends 6 times in a row
// (common/drivers/dshot_commands.hpp). Asked for and carried out only in safe with every engine
// stopped, and dropped the moment that ends: an ESC ignores commands under throttle, and a half-sent
// setting counts for nothing (docs/safety.md rule 18).
#pragma once

#include <stdint.h>

#include <common/drivers/dshot_commands.hpp>
#include <qr/core/board.hpp>
#include <qr/core/flight_types.hpp>

namespace qr {

// The save waits for the direction's repeats: the board sends a DShot frame each control period,
// so 6 frames take 6 periods (12 ms at 500 Hz); 20 ms leaves room at either rate.
inline constexpr uint32_t kEscSaveAfterUs = 20000;

class EscDirection {
 public:
  // The pilot's request: `engine` 0..3, `direction` 1 (normal) or 2 (reversed), the wire's
  // esc_direction. Refused outside safe, with an engine turning, or while one is under way.
  NackReason request(uint8_t engine, uint8_t direction, Mode mode, const EngineCommand& engines, uint32_t now_us) {
    if (engine >= 4 || (direction != 1 && direction != 2)) return NackReason::bad_value;
    if (mode != Mode::safe) return NackReason::not_from_this_mode;
    if (!engines.all_zero()) return NackReason::engines_running;
    if (pending()) return NackReason::busy;
    engine_ = engine;
    direction_ = direction;
    command_ = static_cast<uint8_t>(direction == 1 ? drivers::DshotCommand::spin_direction_1
                                                   : drivers::DshotCommand::spin_direction_2);
    due_us_ = now_us;
    return NackReason::none;
  }

  bool pending() const { return command_ != 0; }
  uint8_t engine() const { return engine_; }
  uint8_t direction() const { return direction_; }

  // The command due now for its engine (command 0: none). Leaving safe or an engine turning drops
  // what is left of it.
  EscCommand due(Mode mode, const EngineCommand& engines, uint32_t now_us) {
    if (!pending()) return {};
    if (mode != Mode::safe || !engines.all_zero()) {
      command_ = 0;
      return {};
    }
    if (static_cast<int32_t>(now_us - due_us_) < 0) return {};  // not yet (the clock wraps)
    return {command_, static_cast<uint8_t>(1u << engine_)};
  }

  // The board took the command due, or refused it (no ESCs that take commands, or one turned).
  // True when that ends the job: `saved` then says whether the direction is in the ESC.
  bool sent(bool taken, uint32_t now_us, bool& saved) {
    saved = false;
    const bool direction_sent = command_ != static_cast<uint8_t>(drivers::DshotCommand::save_settings);
    if (taken && direction_sent) {
      command_ = static_cast<uint8_t>(drivers::DshotCommand::save_settings);
      due_us_ = now_us + kEscSaveAfterUs;
      return false;
    }
    saved = taken;
    command_ = 0;
    return true;
  }

 private:
  uint8_t engine_ = 0;
  uint8_t direction_ = 1;
  uint8_t command_ = 0;  // the command due next (0: none under way)
  uint32_t due_us_ = 0;
};

}  // namespace qr
