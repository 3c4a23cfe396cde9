// QR -> PC messages that answer or inform: ack, nack, parameter reports and debug text.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/message_table.hpp>
#include <common/nack_reason.hpp>

namespace wire {

constexpr bool is_acked_type(MessageType type) {
  const MessageSpec* spec = message_spec(type);
  return spec != nullptr && spec->acked;
}

// "Request `type` number `seq` is done." Naming both means an ack that arrives late, for a request
// since replaced by a newer one of the same type, is not taken for the newer one's.
struct Ack {
  static constexpr MessageType kType = MessageType::ack;
  MessageType type = MessageType::mode_change;
  uint8_t seq = 0;

  constexpr bool operator==(const Ack&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.type);
    v(m.seq);
  }
  constexpr bool valid() const { return is_acked_type(type); }
};

// "Request `type` number `seq` was received and refused, because `reason`." Like an ack it ends the
// resending; unlike an ack it says nothing was changed.
struct Nack {
  static constexpr MessageType kType = MessageType::nack;
  MessageType type = MessageType::mode_change;
  uint8_t seq = 0;
  NackReason reason = NackReason::bad_value;

  constexpr bool operator==(const Nack&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.type);
    v(m.seq);
    v(m.reason);
  }
  constexpr bool valid() const {
    return is_acked_type(type) && reason != NackReason::none && find_nack_reason(reason) != nullptr;
  }
};

// A parameter's current raw value, sent after every param_set that changed it and for param_get.
struct ParamReport {
  static constexpr MessageType kType = MessageType::param_report;
  uint8_t id = 0;
  int32_t value = 0;

  constexpr bool operator==(const ParamReport&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.id);
    v(m.value);
  }
  constexpr bool valid() const { return true; }
};

inline constexpr size_t kDebugTextChars = 9;

// A piece of the QR's debug text stream: up to 9 characters, NUL-padded. The console appends the
// pieces and breaks lines at '\n'; a lost piece costs at most 9 characters of a debug line.
struct DebugText {
  static constexpr MessageType kType = MessageType::debug_text;
  char text[kDebugTextChars] = {};

  constexpr bool operator==(const DebugText&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.text);
  }

  constexpr size_t length() const {
    size_t n = 0;
    while (n < kDebugTextChars && text[n] != '\0') ++n;
    return n;
  }
  // NUL only as padding at the end, so every piece has exactly one encoding.
  constexpr bool valid() const {
    for (size_t i = length(); i < kDebugTextChars; ++i) {
      if (text[i] != '\0') return false;
    }
    return true;
  }

  // Takes up to 9 characters of `chars` (stopping at a NUL) and returns how many it took, so a
  // longer message is sent as a loop of pieces.
  constexpr size_t fill(const char* chars, size_t count) {
    const size_t limit = count < kDebugTextChars ? count : kDebugTextChars;
    size_t n = 0;
    for (; n < limit && chars[n] != '\0'; ++n) text[n] = chars[n];
    for (size_t i = n; i < kDebugTextChars; ++i) text[i] = '\0';
    return n;
  }
};

}  // namespace wire
