// docs/protocol.md's field tables as a client written from the page would read them: each
// message's fields (offset, type, name) and the range each row states, and a check of bytes off
// the wire against those ranges. The page is read, not the code, so that what the firmware sends
// is judged by the contract other clients were given (issue 30: the page said mode 0..5 while the
// QR sent 6 in height hold, and a client checking the field dropped every attitude frame).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace protocol_page {

// One integer of a row's type.
struct Scalar {
  bool is_signed = false;
  size_t bytes = 1;
  std::string name() const;  // "u8", "i16", ...
};

// What one row's "unit / range" cell says a value may be. Empty: the row states no range (a unit,
// a meaning); the value may be anything its type holds.
struct Range {
  std::optional<long long> min, max;  // "0..1000", "saturated at 65535"
  // "0..4 (sensor), 0..6 (telemetry)": per message of a shared table, by the start of its name.
  std::map<std::string, std::pair<long long, long long>> for_message;
  std::optional<uint32_t> bits;  // "bit 0 ..., bit 4 ...; other bits 0": the bits allowed
  std::string below;             // "0..count−1": less than that field of the same frame
  std::string at_most;           // "mean ≤ max", "≤ capacity_lines": at most that field of the same frame
  bool acked_type = false;       // "an acked type": a type byte section 3 marks acked
  bool nul_padding = false;      // "`0x00` only as padding": characters, then only 0x00 to the end
  // "+1 per attitude frame (wraps)": one more than the frame before (a sender's promise, checked
  // across frames, not by check()).
  bool counter = false;
  // "within the parameter's range": the min..max parameters.md gives the parameter the row's
  // message names in its id field.
  bool parameter_range = false;
  std::string same_as;  // "as telemetry_attitude": that message's field of the same name
  // "other bits 0 (ignore them)", "a client takes any number": what the QR sends, no decoding rule.
  bool sender_only = false;

  bool states_a_range() const;   // of its own, "as <message>" aside
  std::string describe() const;  // as the page says it, for messages
};

struct Field {
  int line = 0;       // in the page, 1-based
  size_t offset = 0;  // within the payload or the record
  Scalar scalar;
  size_t count = 1;                // "4 × u16": 4
  std::vector<std::string> names;  // one, or one per element ("phi, theta, psi")
  std::string cell;                // the unit / range cell as written
  Range range;

  // The name of element `i` (an array's elements share it).
  const std::string& name_of(size_t i) const { return names.size() == count ? names[i] : names[0]; }
};

struct Table {
  int line = 0;                       // the header row's
  std::vector<std::string> messages;  // the heading's message names; empty for a log record
  std::string record;                 // "sensor log record", "telemetry log record"; empty for a message
  size_t stated_bytes = 0;            // the heading's "30 bytes" (records)
  std::vector<Field> fields;

  size_t bytes() const;  // what the rows add up to
  const Field* field(const std::string& name) const;
};

// A row of section 3's message table.
struct MessageRow {
  uint8_t type = 0;
  std::string name;
  bool qr_to_pc = false;
  size_t payload_bytes = 0;
  bool acked = false;
};

struct Page {
  std::vector<MessageRow> messages;
  std::vector<Table> tables;
  size_t task_rows = 0;  // section 5.2's task table: N of "0..N−1"
  // Rows and tables the reader could not read, each with its line: a row it cannot read is a row
  // whose range nothing checks, so each is a failure.
  std::vector<std::string> errors;

  const MessageRow* message(const std::string& name) const;
  const MessageRow* message(uint8_t type) const;
  const Table* table_of(const std::string& message_name) const;  // a message's field table
  const Table* record(const std::string& record_name) const;
  // The range a field's row states, with "as <message>" followed to that message's row.
  const Range& range_of(const Table& table, const Field& field) const;
};

Page read_page(const std::string& text);
Page read_page_file(const std::string& path);

// A value that breaks a row's range: where, which field, what it was, what the row says.
struct Violation {
  int line = 0;
  std::string field;  // "telemetry_attitude.mode"
  long long value = 0;
  std::string says;
  std::string text() const;
};

// The integers a row's bytes hold, read little-endian from `bytes` as the page lays them out.
std::vector<long long> values_of(const Field& field, const uint8_t* bytes, size_t length);

// Checks one payload (or a log record's flat bytes) of `table` against every row's range.
// `message` names the message it came as (for "0..4 (sensor)"), or the record. With
// `decoding_rules_only`, sender-only promises are skipped: what a decoder may refuse.
// Whether `value` is within parameter `id`'s range (parameters.md); none: not judged.
using ParameterRange = bool (*)(long long id, long long value);

std::vector<Violation> check(const Page& page, const Table& table, const std::string& message, const uint8_t* bytes,
                             size_t length, bool decoding_rules_only = false, ParameterRange parameter_ok = nullptr);

}  // namespace protocol_page
