// The code's side of docs/protocol.md's field tables: each QR -> PC message struct and log record,
// its wire layout as a list of integer types, and its reference decoder (read_fields: the
// struct's valid()). The page tests compare these with the tables a client reads.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>
#include <type_traits>
#include <vector>

#include <common/log_records.hpp>
#include <common/messages.hpp>

namespace protocol_page {

// The integers a struct's fields() visits, in wire order: "u8", "i16", ... (text travels as u8).
class LayoutOf {
 public:
  void operator()(uint8_t) { types.push_back("u8"); }
  void operator()(char) { types.push_back("u8"); }
  void operator()(int8_t) { types.push_back("i8"); }
  void operator()(uint16_t) { types.push_back("u16"); }
  void operator()(int16_t) { types.push_back("i16"); }
  void operator()(uint32_t) { types.push_back("u32"); }
  void operator()(int32_t) { types.push_back("i32"); }
  template <wire::WireEnum E>
  void operator()(E) {
    (*this)(wire::underlying_t<E>{});
  }
  template <class T, size_t N>
  void operator()(const T (&array)[N]) {
    for (const T& element : array) (*this)(element);
  }

  std::vector<std::string> types;
};

// What the code knows of one thing the QR sends: its name as the page's heading gives it, its
// layout, and whether its decoder takes these bytes.
struct CodeMessage {
  std::string name;  // "telemetry_attitude", or "sensor log record"
  bool record = false;
  std::vector<std::string> layout;
  std::vector<uint8_t> default_bytes;  // a default-constructed one, encoded
  bool (*decodes)(const uint8_t* bytes, size_t length) = nullptr;
};

template <class Record>
CodeMessage code_message(std::string name, bool record) {
  CodeMessage m;
  m.name = std::move(name);
  m.record = record;
  const Record defaults{};
  LayoutOf layout;
  Record::fields(defaults, layout);
  m.layout = layout.types;
  m.default_bytes.resize(wire::wire_size<Record>());
  wire::write_fields(defaults, m.default_bytes.data(), m.default_bytes.size());
  m.decodes = [](const uint8_t* bytes, size_t length) {
    Record out;
    return wire::read_fields(bytes, length, out);
  };
  return m;
}

// Every message the QR sends (the table's QR -> PC rows) and both log records.
inline std::vector<CodeMessage> qr_sends() {
  std::vector<CodeMessage> out;
  [&]<class... Msgs>(wire::MessageList<Msgs...>) {
    (
        [&] {
          const wire::MessageSpec& spec = *wire::message_spec(Msgs::kType);
          if (spec.direction == wire::Direction::qr_to_pc) out.push_back(code_message<Msgs>(spec.name, false));
        }(),
        ...);
  }(wire::AllMessages{});
  out.push_back(code_message<wire::SensorLogRecord>("sensor log record", true));
  out.push_back(code_message<wire::TelemetryLogRecord>("telemetry log record", true));
  return out;
}

}  // namespace protocol_page
