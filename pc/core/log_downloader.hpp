// Downloads the QR's two logs into CSV files: the sensor log, then the telemetry log. How many
// lines each has comes from the QR's log_status; which lines are in and what to ask for next is
// the wire library's wire::LogDownloader (the log streamed once, the lost parts asked for again
// by part while it goes on). This class runs the two downloads one after the other, gives up when
// nothing new arrives for a while, says how far it is, and writes the files.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <common/log_downloader.hpp>
#include <common/log_records.hpp>
#include <common/nack_reason.hpp>
#include <common/requests.hpp>
#include <pc/core/console_log.hpp>

namespace qrterm {

class LogDownloader {
 public:
  // No new line for this long (through several re-requests): the download is given up.
  static constexpr uint32_t kGiveUpMs = 5000;

  struct Hooks {
    std::function<void(const wire::LogDownload&)> request;  // send it (acked)
    std::function<void(const wire::LogResend&)> resend;     // send it (acked)
    // A log_resend is still unanswered: a new one would replace it, so none is made meanwhile.
    std::function<bool()> resend_pending;
    std::function<void(Severity, const std::string&)> note;                      // tell the pilot
    std::function<std::unique_ptr<std::ostream>(const std::string& name)> open;  // a file in the log folder
    std::function<bool(const std::string& from, const std::string& to)> rename;  // a file of the log folder
  };

  explicit LogDownloader(Hooks hooks);
  ~LogDownloader();

  bool active() const { return kind_ != Kind::idle; }

  // The pilot's download key: starts with what the QR last said about its logs (empty: it has not
  // said yet). Refuses, with a note, while a download runs, before the QR has said, while it logs
  // and when its logs are empty; skips a log without lines.
  void start(const std::optional<wire::LogStatus>& status, uint32_t now_ms);

  // The QR refused our log_download (matched by the caller on type and seq).
  void on_nack(wire::NackReason reason);

  // Every frame the console accepts, before it is handled, with its parser's damage count
  // (bytes skipped and checks failed so far): parts next to damage are not kept (a lost byte can
  // splice a part that passes the 8-bit check, wire::LogDownloader).
  void frame_accepted(uint32_t damage, uint32_t now_ms);

  void on_part(const wire::SensorLogPart& part, uint32_t now_ms);
  void on_part(const wire::TelemetryLogPart& part, uint32_t now_ms);

  // Asks for what is due, finishes a log when it is whole, gives up when nothing comes.
  void tick(uint32_t now_ms);

  // "sensor log: 812 of 1200 lines, 67 %, 4 s left" while running (the time left at the rate
  // so far, once there is one); empty when idle.
  std::string status(uint32_t now_ms) const;

 private:
  enum class Kind : uint8_t { idle, sensor, telemetry };

  template <class Record>
  struct Download {
    wire::LogDownloader<Record> lines;
    std::map<uint16_t, Record> records;
  };

  void begin(Kind kind, uint32_t now_ms);
  template <class Record>
  void take(Download<Record>& download, const wire::LogPart<Record>& part, Kind kind, uint32_t now_ms);
  template <class Record>
  void write(Download<Record>& download, const char* name);
  template <class Record>
  void step(Download<Record>& download, wire::LogKind log, uint32_t now_ms);
  void stop(Severity severity, const std::string& why);

  Hooks hooks_;
  Kind kind_ = Kind::idle;
  wire::LogStatus status_;
  uint32_t last_progress_ms_ = 0;
  uint32_t began_ms_ = 0;   // this log's download started
  uint32_t downloads_ = 0;  // numbers the files of each download: sensor_log_1.csv, ...
  // Each holds an 8 KiB map of the lines received and 24 KiB of lines being collected: on the heap,
  // and only while downloading.
  std::unique_ptr<Download<wire::SensorLogRecord>> sensor_;
  std::unique_ptr<Download<wire::TelemetryLogRecord>> telemetry_;
};

}  // namespace qrterm
