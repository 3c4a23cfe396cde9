// Downloads the QR's two logs (sensor, then telemetry) into CSV files. The QR sends the lines
// asked for as parts, then falls silent; the protocol has no end marker and no line count, so a
// log is taken as complete after kQuietMs without a part. Lines missing below the highest line
// seen are asked for again by number, a few times, then reported missing. Lines missing after the
// highest one seen cannot be told from the end of the log.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>

#include <common/log_records.hpp>
#include <common/nack_reason.hpp>
#include <common/requests.hpp>
#include <pc/core/console_log.hpp>

namespace qrterm {

class LogDownloader {
 public:
  static constexpr uint32_t kQuietMs = 1000;
  static constexpr int kAsksPerLine = 3;

  struct Hooks {
    std::function<void(const wire::LogDownload&)> request;                      // send it (acked)
    std::function<void(Severity, const std::string&)> note;                     // tell the pilot
    std::function<std::unique_ptr<std::ostream>(const std::string& name)> open;  // a file in the log folder
  };

  explicit LogDownloader(Hooks hooks) : hooks_(std::move(hooks)) {}

  bool active() const { return phase_ != Phase::idle; }
  void start(uint32_t now_ms);

  // Answers to our log_download request (matched by the caller on type and seq).
  void on_ack(uint32_t now_ms);
  void on_nack(wire::NackReason reason);
  void on_gave_up();

  void on_part(const wire::SensorLogPart& part, uint32_t now_ms);
  void on_part(const wire::TelemetryLogPart& part, uint32_t now_ms);

  // Ends a log after the quiet time: asks for missing lines or writes the file and moves on.
  void tick(uint32_t now_ms);

  // "telemetry log: 312 lines" while running; empty when idle.
  std::string status() const;

 private:
  enum class Phase : uint8_t { idle, waiting_for_ack, receiving };

  template <class Record>
  struct Collection {
    wire::LogLineAssembler<Record> assembler;
    std::map<uint16_t, Record> lines;
    void clear() { *this = Collection{}; }
  };

  template <class Record>
  void take(Collection<Record>& collection, const wire::LogPart<Record>& part, wire::LogKind kind, uint32_t now_ms);
  template <class Record>
  void finish(Collection<Record>& collection, const char* name);

  void ask(wire::LogKind kind, uint16_t first_line, uint16_t count, uint32_t now_ms);
  void finish_current();
  void stop(Severity severity, const std::string& why);

  Hooks hooks_;
  Phase phase_ = Phase::idle;
  wire::LogKind kind_ = wire::LogKind::sensor;
  uint32_t last_activity_ms_ = 0;
  uint32_t downloads_ = 0;  // numbers the files of each download: sensor_log_1.csv, ...
  std::map<uint16_t, int> asks_;  // line -> times asked for again
  Collection<wire::SensorLogRecord> sensor_;
  Collection<wire::TelemetryLogRecord> telemetry_;
};

}  // namespace qrterm
