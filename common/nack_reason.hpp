// Why the QR refused a request: the third byte of a nack. The first six are the safety machine's
// refusals, in its order, then the protocol's own, then the safety machine's later ones.
#pragma once

#include <stdint.h>

namespace wire {

enum class NackReason : uint8_t {
  none = 0,  // never sent: "no refusal", i.e. the request gets an ack
  not_from_this_mode = 1,
  controls_not_neutral = 2,
  engines_running = 3,
  not_calibrated = 4,
  battery_low = 5,
  unknown_mode = 6,
  bad_value = 7,          // a field out of its range (e.g. a parameter value outside the table's range)
  unknown_parameter = 8,  // no parameter with that id
  busy = 9,               // e.g. a log download while logging
  not_supported = 10,     // a request this firmware does not carry out
  not_flying = 11,        // height hold asked for on the ground: there is no height to hold
  over_budget = 12,       // a stream the line cannot carry beside telemetry (stream_budget.hpp)
  radio_is_pilot = 13,    // a flight mode asked for by the PC while the radio flies: its arm switch arms
  imu_fault = 14,         // leaving safe while the IMU's driver does not stream (docs/safety.md rule 20)
  barometer_fault = 15,   // height hold while the barometer's driver does not measure (rule 20)
  sign_check = 16,        // the vehicle answers a loop the wrong way (docs/safety.md rule 21)
};

struct NackReasonSpec {
  NackReason reason;
  const char* name;
  const char* text;  // what the console shows
};

inline constexpr NackReasonSpec kNackReasons[] = {
    {NackReason::not_from_this_mode, "not_from_this_mode", "not allowed from the current mode"},
    {NackReason::controls_not_neutral, "controls_not_neutral", "sticks and lift not neutral"},
    {NackReason::engines_running, "engines_running", "engines are running"},
    {NackReason::not_calibrated, "not_calibrated", "sensors not calibrated"},
    {NackReason::battery_low, "battery_low", "battery low"},
    {NackReason::unknown_mode, "unknown_mode", "no such mode"},
    {NackReason::bad_value, "bad_value", "value out of range"},
    {NackReason::unknown_parameter, "unknown_parameter", "no such parameter"},
    {NackReason::busy, "busy", "busy, try again later"},
    {NackReason::not_supported, "not_supported", "not supported by this firmware"},
    {NackReason::not_flying, "not_flying", "not flying: nothing to hold"},
    {NackReason::over_budget, "over_budget", "the line cannot carry it beside control and telemetry"},
    {NackReason::radio_is_pilot, "radio_is_pilot", "the radio is the pilot: arm with its switch"},
    {NackReason::imu_fault, "imu_fault", "the IMU is not healthy (its faults are in the debug text)"},
    {NackReason::barometer_fault, "barometer_fault", "the barometer is not healthy: no height to hold"},
    {NackReason::sign_check, "sign_check", "a loop answers the wrong way (the debug text names the axis)"},
};

constexpr const NackReasonSpec* find_nack_reason(NackReason reason) {
  for (const NackReasonSpec& spec : kNackReasons) {
    if (spec.reason == reason) return &spec;
  }
  return nullptr;
}

}  // namespace wire
