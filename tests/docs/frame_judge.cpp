#include "frame_judge.hpp"

#include <cstdio>

namespace protocol_page {
namespace {

constexpr size_t kViolationsKept = 20;

std::string hex(const uint8_t* bytes, size_t n) {
  std::string s;
  char b[4];
  for (size_t i = 0; i < n; ++i) {
    std::snprintf(b, sizeof b, "%s%02X", i == 0 ? "" : " ", bytes[i]);
    s += b;
  }
  return s;
}

// "sensor_log_part" carries lines of the "sensor log record" (section 8).
std::string record_of(const std::string& part_message) {
  const size_t at = part_message.find("_log_part");
  return at == std::string::npos ? std::string() : part_message.substr(0, at) + " log record";
}

}  // namespace

void FrameJudge::violation(const std::string& text) {
  if (violation_count_++ < kViolationsKept) violations_.push_back(text);
}

void FrameJudge::frame(const wire::Frame& frame, const std::string& when) {
  const uint8_t type = static_cast<uint8_t>(frame.type);
  const MessageRow* row = page_.message(type);
  if (row == nullptr || !row->qr_to_pc) {
    violation(when + ": a frame of type " + hex(&type, 1) + ", which section 3 does not list as QR->PC");
    return;
  }
  ++frames_[row->name];
  const Table* table = page_.table_of(row->name);
  if (table == nullptr) {
    violation(when + ": " + row->name + " has no field table");
    return;
  }
  if (frame.length != table->bytes()) {
    violation(when + ": " + row->name + " of " + std::to_string(frame.length) + " bytes, the table adds up to " +
              std::to_string(table->bytes()));
    return;
  }
  judge(*table, row->name, frame.payload, frame.length, when);
  if (!record_of(row->name).empty()) log_part(*table, row->name, frame.payload, frame.length, when);
}

void FrameJudge::judge(const Table& table, const std::string& message, const uint8_t* bytes, size_t length,
                       const std::string& when) {
  for (const Violation& v : check(page_, table, message, bytes, length, false, parameter_ok_))
    violation(v.text() + " (" + when + "; bytes " + hex(bytes, length) + ")");
  const std::string who = message.empty() ? table.record : message;
  for (const Field& f : table.fields) {
    const std::vector<long long> values = values_of(f, bytes, length);
    for (size_t k = 0; k < values.size(); ++k) {
      const long long v = values[k];
      Seen& s = seen_[who + "." + f.name_of(k)];
      s.min = std::min(s.min, v);
      s.max = std::max(s.max, v);
      s.bits |= static_cast<unsigned long long>(v);
      if (f.scalar.bytes == 1) ++s.values[v];
      ++s.count;
    }
    // "+1 per attitude frame (wraps)": a step of 0 repeats a number; a larger one is telemetry the
    // line or the QR's transmit queue lost, which the number is there to show.
    if (page_.range_of(table, f).counter && !values.empty()) {
      const std::string key = who + "." + f.names[0];
      const auto last = last_counter_.find(key);
      if (last != last_counter_.end()) {
        const long long modulo = 1LL << (8 * f.scalar.bytes);
        const long long step = ((values[0] - last->second) % modulo + modulo) % modulo;
        if (step == 0) {
          violation("docs/protocol.md:" + std::to_string(f.line) + ": " + key + " " + std::to_string(values[0]) +
                    " twice in a row (" + when + ")");
        } else if (step != 1) {
          ++counter_gaps_;
        }
      }
      last_counter_[key] = values[0];
    }
  }
}

void FrameJudge::log_part(const Table& table, const std::string& message, const uint8_t* payload, size_t length,
                          const std::string& when) {
  const Table* record = page_.record(record_of(message));
  const Field* line_field = table.field("line");
  const Field* part_field = table.field("part");
  const Field* data_field = table.field("data");
  if (record == nullptr || line_field == nullptr || part_field == nullptr || data_field == nullptr) {
    violation(when + ": " + message + ": no " + record_of(message) + " table, or no line, part and data rows");
    return;
  }
  const long long line = values_of(*line_field, payload, length)[0];
  const long long part = values_of(*part_field, payload, length)[0];
  const std::vector<long long> data = values_of(*data_field, payload, length);
  const size_t parts = record->bytes() / data.size();
  if (part < 0 || static_cast<size_t>(part) >= parts) return;  // out of range: check() said so
  Line& l = lines_[message][line];
  l.flat.resize(record->bytes());
  for (size_t i = 0; i < data.size(); ++i)
    l.flat[static_cast<size_t>(part) * data.size() + i] = static_cast<uint8_t>(data[i]);
  l.parts |= 1u << part;
  if (!l.judged && l.parts == (1u << parts) - 1u) {
    l.judged = true;
    judge(*record, "", l.flat.data(), l.flat.size(), when + ", " + record->record + " line " + std::to_string(line));
  }
}

size_t FrameJudge::whole_lines(const std::string& part_message) const {
  const auto it = lines_.find(part_message);
  if (it == lines_.end()) return 0;
  size_t n = 0;
  for (const auto& entry : it->second) n += entry.second.judged ? 1 : 0;
  return n;
}

}  // namespace protocol_page
