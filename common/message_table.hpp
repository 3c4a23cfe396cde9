// Every message the wire carries, in one table: type byte, payload length, whether it is
// acknowledged, who sends it, and its name. The parser, the encoder, the resend queue and the
// request dedup all read this table; none of them has a switch over message types.
//
// Type bytes are chosen so that
//  - the top bit tells the direction (clear: PC -> QR, set: QR -> PC),
//  - every type byte has even parity, so any two differ in at least two bits: a single flipped
//    bit in the type byte never turns one message into another one of a different length
//    (which the check byte could not be relied on to catch, as it would then cover other bytes),
//  - none is 0x00..0x0F or 0xF0..0xFF (the high bytes of small positive and negative numbers,
//    the most common payload bytes) and none is a printable character (debug text): when the
//    parser hunts for a frame start inside old payload bytes, 'M' followed by such a byte is
//    rarely taken for a frame (PC -> QR types may be printable since observable_get: the QR's
//    receiver never sees text),
//  - none is 'M' itself.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace wire {

enum class MessageType : uint8_t {
  // PC -> QR
  control = 0x11,
  mode_change = 0x12,
  param_set = 0x14,
  param_get = 0x17,
  log_start = 0x18,
  log_stop = 0x1B,
  log_download = 0x1D,
  exit = 0x1E,
  // Printable, unlike the rest: the eight even-parity bytes 0x10..0x1F are taken. Only the QR
  // accepts these, and nothing it receives is text (docs/protocol.md section 3).
  observable_get = 0x22,
  stream_request = 0x41,
  // Four bits from every other PC -> QR type: no two-bit change makes it one of them.
  log_resend = 0x6C,
  // Its only neighbour two bits away is param_get.
  motor_test = 0x77,
  // Two bits from log_stop and motor_test, of other lengths: no byte left is further from all.
  esc_direction = 0x7B,
  // QR -> PC
  ack = 0x81,
  nack = 0x82,
  param_report = 0x84,
  debug_text = 0x87,
  telemetry_attitude = 0x88,
  telemetry_rates = 0x8B,
  telemetry_engines = 0x8D,
  telemetry_setpoints = 0x8E,
  telemetry_system = 0x90,
  telemetry_link = 0x93,
  sensor_log_part = 0x95,
  telemetry_log_part = 0x96,
  telemetry_task = 0x99,
  log_status = 0x9C,
  telemetry_height = 0x9F,
  telemetry_radio = 0xA0,
  telemetry_rpm = 0xA3,
  // Their bytes keep a two-bit change of the type from giving a type of another length, where one
  // was free (docs/protocol.md section 3).
  observable_info = 0xEB,
  observable_text = 0xE7,
  observable_samples = 0xE8,
};

enum class Direction : uint8_t { pc_to_qr = 1, qr_to_pc = 2 };

// Which directions a receiver accepts: the QR listens to the PC and vice versa; a sniffer or a
// test may listen to both.
enum class Listen : uint8_t { pc_to_qr = 1, qr_to_pc = 2, both = 3 };

constexpr bool listens_to(Listen listen, Direction direction) {
  return (static_cast<uint8_t>(listen) & static_cast<uint8_t>(direction)) != 0;
}

struct MessageSpec {
  MessageType type;
  uint8_t payload_length;  // fixed per type, 0..kMaxPayloadBytes
  bool acked;              // re-sent until acknowledged; payload byte 0 is its sequence number
  Direction direction;
  const char* name;
  // Commands what the vehicle does (its mode, its parameters, its logs, the firmware's end): the
  // frame carries a 24-bit guard after the payload (frame.hpp), so noise cannot make one.
  bool guarded;
};

inline constexpr MessageSpec kMessageTable[] = {
    {MessageType::control, 8, false, Direction::pc_to_qr, "control", false},
    {MessageType::mode_change, 2, true, Direction::pc_to_qr, "mode_change", true},
    {MessageType::param_set, 6, true, Direction::pc_to_qr, "param_set", true},
    {MessageType::param_get, 2, true, Direction::pc_to_qr, "param_get", false},
    {MessageType::log_start, 2, true, Direction::pc_to_qr, "log_start", true},
    {MessageType::log_stop, 1, true, Direction::pc_to_qr, "log_stop", true},
    {MessageType::log_download, 6, true, Direction::pc_to_qr, "log_download", false},
    {MessageType::exit, 1, true, Direction::pc_to_qr, "exit", true},
    {MessageType::observable_get, 2, true, Direction::pc_to_qr, "observable_get", false},
    {MessageType::stream_request, 8, true, Direction::pc_to_qr, "stream_request", false},
    {MessageType::log_resend, 9, true, Direction::pc_to_qr, "log_resend", false},
    {MessageType::motor_test, 4, true, Direction::pc_to_qr, "motor_test", true},
    {MessageType::esc_direction, 3, true, Direction::pc_to_qr, "esc_direction", true},
    {MessageType::ack, 2, false, Direction::qr_to_pc, "ack", false},
    {MessageType::nack, 3, false, Direction::qr_to_pc, "nack", false},
    {MessageType::param_report, 5, false, Direction::qr_to_pc, "param_report", false},
    {MessageType::debug_text, 9, false, Direction::qr_to_pc, "debug_text", false},
    {MessageType::telemetry_attitude, 9, false, Direction::qr_to_pc, "telemetry_attitude", false},
    {MessageType::telemetry_rates, 6, false, Direction::qr_to_pc, "telemetry_rates", false},
    {MessageType::telemetry_engines, 8, false, Direction::qr_to_pc, "telemetry_engines", false},
    {MessageType::telemetry_setpoints, 8, false, Direction::qr_to_pc, "telemetry_setpoints", false},
    {MessageType::telemetry_system, 8, false, Direction::qr_to_pc, "telemetry_system", false},
    {MessageType::telemetry_link, 9, false, Direction::qr_to_pc, "telemetry_link", false},
    {MessageType::sensor_log_part, 9, false, Direction::qr_to_pc, "sensor_log_part", false},
    {MessageType::telemetry_log_part, 9, false, Direction::qr_to_pc, "telemetry_log_part", false},
    {MessageType::telemetry_task, 7, false, Direction::qr_to_pc, "telemetry_task", false},
    {MessageType::log_status, 7, false, Direction::qr_to_pc, "log_status", false},
    {MessageType::telemetry_height, 9, false, Direction::qr_to_pc, "telemetry_height", false},
    {MessageType::telemetry_radio, 9, false, Direction::qr_to_pc, "telemetry_radio", false},
    {MessageType::telemetry_rpm, 8, false, Direction::qr_to_pc, "telemetry_rpm", false},
    {MessageType::observable_info, 6, false, Direction::qr_to_pc, "observable_info", false},
    {MessageType::observable_text, 9, false, Direction::qr_to_pc, "observable_text", false},
    {MessageType::observable_samples, 9, false, Direction::qr_to_pc, "observable_samples", false},
};

inline constexpr size_t kMessageCount = sizeof(kMessageTable) / sizeof(kMessageTable[0]);

constexpr uint8_t type_byte(MessageType type) { return static_cast<uint8_t>(type); }

// Compile-time lookup, for static checks on message structs. Run time uses find_message().
constexpr const MessageSpec* message_spec(MessageType type) {
  for (const MessageSpec& spec : kMessageTable) {
    if (spec.type == type) return &spec;
  }
  return nullptr;
}

constexpr uint8_t count_acked_types() {
  uint8_t count = 0;
  for (const MessageSpec& spec : kMessageTable) count = static_cast<uint8_t>(count + (spec.acked ? 1 : 0));
  return count;
}

// Number of acknowledged request types: the size of the per-type state in the resend queue and
// the request dedup.
inline constexpr uint8_t kAckedTypeCount = count_acked_types();
inline constexpr uint8_t kNoAckSlot = 0xFF;

// The table row for a type byte, or nullptr when the byte names no message. O(1).
const MessageSpec* find_message(uint8_t type);

// 0..kAckedTypeCount-1 for an acknowledged type, kNoAckSlot otherwise. O(1).
uint8_t ack_slot(MessageType type);

// The acknowledged type that owns a slot (inverse of ack_slot).
MessageType acked_type_at(uint8_t slot);

const char* message_name(MessageType type);

}  // namespace wire
