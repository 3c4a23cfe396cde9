#include <pc/core/log_downloader.hpp>

#include <pc/core/csv_writer.hpp>
#include <pc/core/log_csv.hpp>

namespace qrterm {

LogDownloader::LogDownloader(Hooks hooks) : hooks_(std::move(hooks)) {}

LogDownloader::~LogDownloader() = default;

void LogDownloader::start(const std::optional<wire::LogStatus>& said, uint32_t now_ms) {
  if (active()) {
    hooks_.note(Severity::warning, "a log download is running already (" + status(now_ms) + ")");
    return;
  }
  if (!said) {
    hooks_.note(Severity::warning, "the QR has not said yet what its logs hold (no log_status): try again");
    return;
  }
  const wire::LogStatus& status = *said;
  if ((status.flags & (wire::kLogStatusSensorOn | wire::kLogStatusTelemetryOn)) != 0) {
    hooks_.note(Severity::warning, "the QR is logging: stop the logs first (t), then download (g)");
    return;
  }
  if (status.sensor_lines == 0 && status.telemetry_lines == 0) {
    hooks_.note(Severity::warning, "the QR's logs are empty (s starts logging)");
    return;
  }
  status_ = status;
  ++downloads_;
  begin(status.sensor_lines > 0 ? Kind::sensor : Kind::telemetry, now_ms);
}

void LogDownloader::begin(Kind kind, uint32_t now_ms) {
  kind_ = kind;
  last_progress_ms_ = now_ms;
  began_ms_ = now_ms;
  const bool sensor = kind == Kind::sensor;
  const uint16_t lines = sensor ? status_.sensor_lines : status_.telemetry_lines;
  if (sensor) {
    sensor_ = std::make_unique<Download<wire::SensorLogRecord>>();
    sensor_->lines.begin(lines);
  } else {
    telemetry_ = std::make_unique<Download<wire::TelemetryLogRecord>>();
    telemetry_->lines.begin(lines);
  }
  hooks_.note(Severity::info, std::string("log download: ") + (sensor ? "sensor" : "telemetry") + " log, " +
                                  std::to_string(lines) + " lines");
}

void LogDownloader::on_nack(wire::NackReason reason) {
  if (!active()) return;
  const wire::NackReasonSpec* spec = wire::find_nack_reason(reason);
  std::string why = spec != nullptr ? spec->text : "refused";
  if (reason == wire::NackReason::busy) why += " (the QR is logging: stop the logs first, key t)";
  stop(Severity::warning, "log download refused: " + why);
}

template <class Record>
void LogDownloader::take(Download<Record>& download, const wire::LogPart<Record>& part, Kind kind, uint32_t now_ms) {
  // Parts of the other log are leftovers of a request replaced by a newer one.
  if (kind_ != kind) return;
  download.lines.on_part(part, now_ms, [&](const Record& record) {
    download.records.emplace(record.line, record);
    last_progress_ms_ = now_ms;
  });
}

void LogDownloader::frame_accepted(uint32_t damage, uint32_t now_ms) {
  const auto keep = [&](auto& download) {
    download.lines.frame_accepted(damage, [&](const auto& record) {
      download.records.emplace(record.line, record);
      last_progress_ms_ = now_ms;
    });
  };
  if (sensor_) keep(*sensor_);
  if (telemetry_) keep(*telemetry_);
}

void LogDownloader::on_part(const wire::SensorLogPart& part, uint32_t now_ms) {
  if (sensor_) take(*sensor_, part, Kind::sensor, now_ms);
}

void LogDownloader::on_part(const wire::TelemetryLogPart& part, uint32_t now_ms) {
  if (telemetry_) take(*telemetry_, part, Kind::telemetry, now_ms);
}

template <class Record>
void LogDownloader::step(Download<Record>& download, wire::LogKind log, uint32_t now_ms) {
  uint16_t first = 0;
  uint16_t count = 0;
  if (download.lines.next_download(now_ms, first, count)) hooks_.request(wire::LogDownload{0, log, first, count});
  // Only when the last one was answered: the downloader counts what it hands out as asked.
  if (!hooks_.resend || (hooks_.resend_pending && hooks_.resend_pending())) return;
  wire::LogResend resend;
  resend.log = log;
  if (download.lines.next_resend(now_ms, resend)) hooks_.resend(resend);
}

void LogDownloader::tick(uint32_t now_ms) {
  if (!active()) return;
  const bool sensor = kind_ == Kind::sensor;
  const bool done = sensor ? sensor_->lines.done() : telemetry_->lines.done();
  if (done) {
    if (sensor) {
      write(*sensor_, "sensor");
      sensor_.reset();
      if (status_.telemetry_lines > 0) return begin(Kind::telemetry, now_ms);
    } else {
      write(*telemetry_, "telemetry");
      telemetry_.reset();
    }
    kind_ = Kind::idle;
    return;
  }
  if (now_ms - last_progress_ms_ >= kGiveUpMs) {
    return stop(Severity::error, "log download: no new line for " + std::to_string(kGiveUpMs / 1000) +
                                     " s, given up at " + status(now_ms));
  }
  if (sensor) {
    step(*sensor_, wire::LogKind::sensor, now_ms);
  } else {
    step(*telemetry_, wire::LogKind::telemetry, now_ms);
  }
}

// Written under a partial name first and renamed when every line is on the disk: a full disk, a
// folder gone read-only or a console killed part-way leaves a file that says it is partial.
template <class Record>
void LogDownloader::write(Download<Record>& download, const char* name) {
  const std::string stem = std::string(name) + "_log_" + std::to_string(downloads_);
  const std::string file = stem + ".csv", partial = stem + ".partial.csv";
  std::unique_ptr<std::ostream> out = hooks_.open ? hooks_.open(partial) : nullptr;
  if (!out || !out->good()) {
    hooks_.note(Severity::error, std::string(name) + " log not saved: cannot create " + partial +
                                     " (log folder read-only or disk full)");
    return;
  }
  CsvWriter csv(*out, log_header(Record{}));
  size_t written = 0;
  for (const auto& [line, record] : download.records) {
    csv.write(log_row(record));
    if (!out->good()) break;
    ++written;
  }
  out->flush();
  const bool whole = out->good() && written == download.records.size();
  out.reset();  // closed before it is renamed
  if (!whole) {
    hooks_.note(Severity::error, std::string(name) + " log: writing " + partial + " failed after " +
                                     std::to_string(written) + " of " + std::to_string(download.records.size()) +
                                     " lines (disk full or log folder read-only): the file is partial");
    return;
  }
  if (!hooks_.rename || !hooks_.rename(partial, file)) {
    hooks_.note(Severity::error, std::string(name) + " log: all " + std::to_string(written) + " lines are in " +
                                     partial + ", but it could not be renamed " + file);
    return;
  }
  const uint32_t asked_again = download.lines.rerequests();
  hooks_.note(Severity::info, std::string(name) + " log: " + std::to_string(download.records.size()) + " lines -> " +
                                  file + (asked_again > 0 ? " (" + std::to_string(asked_again) + " re-requests)" : ""));
}

void LogDownloader::stop(Severity severity, const std::string& why) {
  hooks_.note(severity, why);
  kind_ = Kind::idle;
  sensor_.reset();
  telemetry_.reset();
}

std::string LogDownloader::status(uint32_t now_ms) const {
  uint32_t received = 0;
  uint32_t lines = 0;
  const char* name = "";
  if (kind_ == Kind::sensor && sensor_) {
    received = sensor_->lines.received();
    lines = sensor_->lines.lines();
    name = "sensor";
  } else if (kind_ == Kind::telemetry && telemetry_) {
    received = telemetry_->lines.received();
    lines = telemetry_->lines.lines();
    name = "telemetry";
  } else {
    return "";
  }
  std::string text = std::string(name) + " log: " + std::to_string(received) + " of " + std::to_string(lines) +
                     " lines, " + std::to_string(lines == 0 ? 100 : received * 100 / lines) + " %";
  const uint32_t elapsed_ms = now_ms - began_ms_;
  if (received > 0 && elapsed_ms > 0) {
    const uint64_t left_ms = uint64_t{lines - received} * elapsed_ms / received;
    text += ", " + std::to_string((left_ms + 999) / 1000) + " s left";
  }
  return text;
}

}  // namespace qrterm
