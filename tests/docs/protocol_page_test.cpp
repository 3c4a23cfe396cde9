// docs/protocol.md's field tables for everything the QR sends, read as a client written from the
// page reads them: every row is read (a row the reader cannot read fails, so no row stops being
// checked in silence), each table lays its message out as the code does, and each range is the
// reference decoder's rule: section 4 says a frame with a field outside section 5's ranges is
// dropped, so a page range narrower than the decoder's drops frames the QR sends (issue 30),
// and one wider lets through frames the console drops. The firmware's frames in flight:
// protocol_flight_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <common/messages.hpp>

#include "message_layouts.hpp"
#include "protocol_page.hpp"

namespace {

using protocol_page::CodeMessage;
using protocol_page::Field;
using protocol_page::Page;
using protocol_page::Table;

std::string page_text() {
  std::ifstream in(QR_PROTOCOL_DOC);
  std::stringstream all;
  all << in.rdbuf();
  return all.str();
}

const Table* table_for(const Page& page, const CodeMessage& m) {
  return m.record ? page.record(m.name) : page.table_of(m.name);
}

std::vector<std::string> page_layout(const Table& table) {
  std::vector<std::string> types;
  for (const Field& f : table.fields) types.insert(types.end(), f.count, f.scalar.name());
  return types;
}

// Writes `value` into element `k` of the row's bytes, little-endian as the page lays it out.
void put(std::vector<uint8_t>& bytes, const Field& f, size_t k, long long value) {
  const size_t from = f.offset + k * f.scalar.bytes;
  for (size_t b = 0; b < f.scalar.bytes; ++b)
    bytes[from + b] = static_cast<uint8_t>(static_cast<unsigned long long>(value) >> (8 * b));
}

// Values worth trying in one row: every value of a byte; for wider rows the type's ends, the
// small numbers and each end of the ranges the page states, and one past each.
std::vector<long long> probes(const Field& f, const protocol_page::Range& r) {
  const unsigned bits = static_cast<unsigned>(8 * f.scalar.bytes);
  const long long lowest = f.scalar.is_signed ? -(1LL << (bits - 1)) : 0;
  const long long highest = f.scalar.is_signed ? (1LL << (bits - 1)) - 1 : (1LL << bits) - 1;
  std::vector<long long> v;
  if (bits == 8) {
    for (long long x = lowest; x <= highest; ++x) v.push_back(x);
    return v;
  }
  v = {lowest, highest, 0, 1, 2, -1};
  const auto around = [&](long long x) { v.insert(v.end(), {x - 1, x, x + 1}); };
  if (r.min) around(*r.min);
  if (r.max) around(*r.max);
  for (const auto& entry : r.for_message) {
    around(entry.second.first);
    around(entry.second.second);
  }
  std::vector<long long> in_type;
  for (long long x : v) {
    if (x >= lowest && x <= highest) in_type.push_back(x);
  }
  std::sort(in_type.begin(), in_type.end());
  in_type.erase(std::unique(in_type.begin(), in_type.end()), in_type.end());
  return in_type;
}

TEST(ProtocolPage, EveryRowOfWhatTheQrSendsIsRead) {
  const Page page = protocol_page::read_page_file(QR_PROTOCOL_DOC);
  for (const std::string& e : page.errors) ADD_FAILURE() << e;
  EXPECT_FALSE(page.messages.empty());
  EXPECT_GT(page.task_rows, 0u);
}

// Every message the QR sends has one field table, its rows add up to section 3's payload length,
// and the rows are the integers the code writes, in its order (a record: its stated size).
TEST(ProtocolPage, EachTableLaysItsMessageOutAsTheCodeDoes) {
  const Page page = protocol_page::read_page_file(QR_PROTOCOL_DOC);
  size_t qr_messages = 0;
  for (const protocol_page::MessageRow& row : page.messages) qr_messages += row.qr_to_pc ? 1 : 0;
  const std::vector<CodeMessage> code = protocol_page::qr_sends();
  EXPECT_EQ(code.size(), qr_messages + 2) << "the QR -> PC rows of section 3 and two log records";
  for (const CodeMessage& m : code) {
    const Table* table = table_for(page, m);
    ASSERT_NE(table, nullptr) << "docs/protocol.md has no field table for " << m.name;
    if (m.record) {
      EXPECT_EQ(table->bytes(), table->stated_bytes) << m.name;
    } else {
      ASSERT_NE(page.message(m.name), nullptr) << m.name;
      EXPECT_EQ(table->bytes(), page.message(m.name)->payload_bytes) << m.name;
    }
    EXPECT_EQ(table->bytes(), m.default_bytes.size()) << m.name;
    EXPECT_EQ(page_layout(*table), m.layout) << m.name << " (docs/protocol.md:" << table->line << ")";
  }
}

// Section 4: a frame is decoded, and one with a field outside section 5's range is dropped. So
// the page's ranges must be the reference decoder's: every row of every message the QR sends, each
// value tried alone in an otherwise default message, is taken by both or refused by both. A row
// that states no range while the decoder refuses values (a rule a client cannot know) fails too.
TEST(ProtocolPage, EachRangeIsTheReferenceDecodersRule) {
  const Page page = protocol_page::read_page_file(QR_PROTOCOL_DOC);
  for (const CodeMessage& m : protocol_page::qr_sends()) {
    const Table* table = table_for(page, m);
    ASSERT_NE(table, nullptr) << m.name;
    ASSERT_EQ(table->bytes(), m.default_bytes.size()) << m.name;
    const std::string as = m.record ? "" : m.name;
    ASSERT_TRUE(m.decodes(m.default_bytes.data(), m.default_bytes.size())) << m.name;
    for (const auto& v : protocol_page::check(page, *table, as, m.default_bytes.data(), m.default_bytes.size(), true))
      ADD_FAILURE() << "a default " << m.name << ": " << v.text();
    for (const Field& f : table->fields) {
      const protocol_page::Range& range = page.range_of(*table, f);
      for (size_t k = 0; k < f.count; ++k) {
        int disagreements = 0;
        for (long long value : probes(f, range)) {
          std::vector<uint8_t> bytes = m.default_bytes;
          put(bytes, f, k, value);
          const bool decoder = m.decodes(bytes.data(), bytes.size());
          const bool page_takes = protocol_page::check(page, *table, as, bytes.data(), bytes.size(), true).empty();
          if (decoder != page_takes && ++disagreements <= 3) {
            ADD_FAILURE() << "docs/protocol.md:" << f.line << ": " << m.name << "." << f.name_of(k) << " = " << value
                          << ": the page " << (page_takes ? "takes" : "refuses") << " it (" << range.describe()
                          << "), the decoder " << (decoder ? "takes" : "refuses") << " it";
          }
        }
      }
    }
  }
}

// Issue 30 as it was: the page said telemetry_attitude's mode was 0..5 while the QR sent 6 in height
// hold. A page one mode short, as that one was, refuses the last mode's attitude frames.
TEST(ProtocolPage, APageOneModeShortRefusesTheLastMode) {
  std::string text = page_text();
  const std::regex row(R"(\| 1 \| u8 \| mode \| 0\.\.(\d+) as in mode_change \|)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, row)) << "the attitude's mode row";
  const int last = std::stoi(m[1].str());
  ASSERT_EQ(last, wire::kModeCount - 1) << "EachRangeIsTheReferenceDecodersRule says more";
  text.replace(static_cast<size_t>(m.position(0)), static_cast<size_t>(m.length(0)),
               "| 1 | u8 | mode | 0.." + std::to_string(last - 1) + " as in mode_change |");
  const Page page = protocol_page::read_page(text);
  EXPECT_TRUE(page.errors.empty());
  const Table* table = page.table_of("telemetry_attitude");
  ASSERT_NE(table, nullptr);
  wire::TelemetryAttitude attitude;
  attitude.mode = static_cast<wire::Mode>(last);
  const wire::FrameBytes frame = wire::encode(attitude);
  const auto violations = protocol_page::check(page, *table, "telemetry_attitude", frame.bytes + 2, frame.size - 3u);
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].field, "telemetry_attitude.mode");
  EXPECT_EQ(violations[0].value, last);
}

// A range the reader does not understand is an error, not a row without a range: a limit in
// other words, bits with nothing said of the others, a type or a name it cannot read.
TEST(ProtocolPage, ARowTheReaderCannotReadFails) {
  const std::string good = page_text();
  const struct {
    const char* row;
    const char* changed;
  } cases[] = {
      {"| 0 | 4 × u16 | engine | 0..1000 each: front, right, back, left |",
       "| 0 | 4 × u16 | engine | at most 1000 each: front, right, back, left |"},
      {"bit 4 flying (the QR's landed detector: not on the ground); other bits 0 (ignore them) |",
       "bit 4 flying (the QR's landed detector: not on the ground) |"},
      {"| 2 | u16 | cpu_load | share of the control period spent in tasks, per mille, 0..1000 |",
       "| 2 | u16 | cpu_load | share of the control period spent in tasks, per mille, 0..1000 or 0..2000 |"},
      {"| 8 | u8 | rx_overruns |", "| 8 | u7 | rx_overruns |"},
      {"| 5 | u8 | flags | as telemetry_attitude |", "| 5 | u8 | flags | as telemetry_attitudes |"},
      {"| 1 | u16 | mean | cycles, mean ≤ max |", "| 1 | u16 | mean | cycles, mean ≤ maximum |"},
  };
  for (const auto& c : cases) {
    std::string text = good;
    const size_t at = text.find(c.row);
    ASSERT_NE(at, std::string::npos) << c.row;
    text.replace(at, std::string(c.row).size(), c.changed);
    EXPECT_FALSE(protocol_page::read_page(text).errors.empty()) << c.changed;
  }
}

}  // namespace
