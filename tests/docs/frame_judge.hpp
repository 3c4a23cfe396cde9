// Judges the QR's frames as a client written from docs/protocol.md would take them: each frame's
// fields read at the page's offsets and checked against the page's ranges, log lines put back
// together from their parts and checked against the record tables, the attitude's tick against
// "+1 per attitude frame". It also keeps what it saw of every field, for the report of ranges the
// flights never reached.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

#include <common/frame.hpp>

#include "protocol_page.hpp"

namespace protocol_page {

struct Seen {
  long long min = std::numeric_limits<long long>::max();
  long long max = std::numeric_limits<long long>::min();
  unsigned long long bits = 0;         // every value OR'd
  std::map<long long, size_t> values;  // for the small fields: how often each value came
  size_t count = 0;
};

class FrameJudge {
 public:
  // `parameter_ok`: parameters.md's ranges, for "within the parameter's range".
  FrameJudge(const Page& page, ParameterRange parameter_ok) : page_(page), parameter_ok_(parameter_ok) {}

  // A frame the console's parser accepted; `when` says where in the flight (for a violation).
  void frame(const wire::Frame& frame, const std::string& when);

  // Another QR from here on: its counters start again.
  void new_flight() { last_counter_.clear(); }

  // Lines of a log whose every part has come (parts of a download), each already judged.
  size_t whole_lines(const std::string& part_message) const;

  const std::vector<std::string>& violations() const { return violations_; }
  size_t violation_count() const { return violation_count_; }
  // "telemetry_attitude.mode", "telemetry log record.mode": what came of each field.
  const std::map<std::string, Seen>& seen() const { return seen_; }
  const std::map<std::string, size_t>& frames() const { return frames_; }
  // The counters' steps that were not +1: lost telemetry, which the page allows (gaps) and a
  // number sent twice, which it does not (a violation).
  size_t counter_gaps() const { return counter_gaps_; }

 private:
  struct Line {
    std::vector<uint8_t> flat;
    uint32_t parts = 0;  // bit k: part k came
    bool judged = false;
  };

  void judge(const Table& table, const std::string& message, const uint8_t* bytes, size_t length,
             const std::string& when);
  void log_part(const Table& table, const std::string& message, const uint8_t* payload, size_t length,
                const std::string& when);
  void violation(const std::string& text);

  const Page& page_;
  ParameterRange parameter_ok_;
  std::vector<std::string> violations_;
  size_t violation_count_ = 0;
  std::map<std::string, Seen> seen_;
  std::map<std::string, size_t> frames_;
  std::map<std::string, long long> last_counter_;
  size_t counter_gaps_ = 0;
  std::map<std::string, std::map<long long, Line>> lines_;  // by part message, by line number
};

}  // namespace protocol_page
