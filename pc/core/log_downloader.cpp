#include <pc/core/log_downloader.hpp>

#include <pc/core/csv_writer.hpp>
#include <pc/core/log_csv.hpp>

namespace qrterm {
namespace {

const char* log_name(wire::LogKind kind) { return kind == wire::LogKind::sensor ? "sensor" : "telemetry"; }

}  // namespace

void LogDownloader::start(uint32_t now_ms) {
  ++downloads_;
  sensor_.clear();
  telemetry_.clear();
  hooks_.note(Severity::info, "log download: asking for the sensor log");
  ask(wire::LogKind::sensor, 0, 0, now_ms);
}

void LogDownloader::ask(wire::LogKind kind, uint16_t first_line, uint16_t count, uint32_t now_ms) {
  kind_ = kind;
  phase_ = Phase::waiting_for_ack;
  last_activity_ms_ = now_ms;
  hooks_.request(wire::LogDownload{0, kind, first_line, count});
}

void LogDownloader::on_ack(uint32_t now_ms) {
  if (phase_ != Phase::waiting_for_ack) return;
  phase_ = Phase::receiving;
  last_activity_ms_ = now_ms;
}

void LogDownloader::on_nack(wire::NackReason reason) {
  if (!active()) return;
  const wire::NackReasonSpec* spec = wire::find_nack_reason(reason);
  std::string why = spec != nullptr ? spec->text : "refused";
  if (reason == wire::NackReason::busy) why += " (the QR is logging: stop the logs first, key t)";
  stop(Severity::warning, std::string("log download refused: ") + why);
}

void LogDownloader::on_gave_up() {
  if (active()) stop(Severity::error, "log download: the QR did not answer");
}

template <class Record>
void LogDownloader::take(Collection<Record>& collection, const wire::LogPart<Record>& part, wire::LogKind kind,
                         uint32_t now_ms) {
  // Parts of the other log, or parts that arrive before the ack (the ack was lost, the lines
  // were not), still count; anything while idle is a leftover of an earlier download.
  if (!active() || kind != kind_) return;
  phase_ = Phase::receiving;
  last_activity_ms_ = now_ms;
  Record record;
  if (collection.assembler.add(part, record) == wire::LogLineAssembler<Record>::Result::complete) {
    collection.lines[record.line] = record;
  }
}

void LogDownloader::on_part(const wire::SensorLogPart& part, uint32_t now_ms) {
  take(sensor_, part, wire::LogKind::sensor, now_ms);
}

void LogDownloader::on_part(const wire::TelemetryLogPart& part, uint32_t now_ms) {
  take(telemetry_, part, wire::LogKind::telemetry, now_ms);
}

void LogDownloader::tick(uint32_t now_ms) {
  if (phase_ != Phase::receiving || now_ms - last_activity_ms_ < kQuietMs) return;
  const auto first_gap = [this](const auto& lines) -> std::pair<uint16_t, uint16_t> {
    if (lines.empty()) return {0, 0};
    const uint32_t last = lines.rbegin()->first;
    for (uint32_t line = 0; line < last; ++line) {
      if (lines.count(static_cast<uint16_t>(line)) != 0 || asks_[static_cast<uint16_t>(line)] >= kAsksPerLine) continue;
      uint32_t end = line + 1;
      while (end < last && lines.count(static_cast<uint16_t>(end)) == 0) ++end;
      return {static_cast<uint16_t>(line), static_cast<uint16_t>(end - line)};
    }
    return {0, 0};
  };
  const auto [first, count] = kind_ == wire::LogKind::sensor ? first_gap(sensor_.lines) : first_gap(telemetry_.lines);
  if (count > 0) {
    for (uint32_t line = first; line < uint32_t{first} + count; ++line) ++asks_[static_cast<uint16_t>(line)];
    ask(kind_, first, count, now_ms);
    return;
  }
  finish_current();
  if (kind_ == wire::LogKind::sensor) {
    hooks_.note(Severity::info, "log download: asking for the telemetry log");
    asks_.clear();
    ask(wire::LogKind::telemetry, 0, 0, now_ms);
  } else {
    phase_ = Phase::idle;
    asks_.clear();
  }
}

template <class Record>
void LogDownloader::finish(Collection<Record>& collection, const char* name) {
  size_t missing = 0;
  if (!collection.lines.empty()) missing = size_t{collection.lines.rbegin()->first} + 1 - collection.lines.size();
  if (collection.lines.empty()) {
    hooks_.note(Severity::warning, std::string(name) + " log: empty (nothing logged, or the QR sent nothing)");
    return;
  }
  const std::string file = std::string(name) + "_log_" + std::to_string(downloads_) + ".csv";
  std::unique_ptr<std::ostream> out = hooks_.open ? hooks_.open(file) : nullptr;
  if (!out) {
    hooks_.note(Severity::error, "cannot write " + file);
    return;
  }
  CsvWriter csv(*out, log_header(Record{}));
  for (const auto& [line, record] : collection.lines) csv.write(log_row(record));
  out->flush();
  std::string text = std::string(name) + " log: " + std::to_string(collection.lines.size()) + " lines -> " + file;
  if (missing > 0) text += ", " + std::to_string(missing) + " lines missing";
  hooks_.note(missing > 0 ? Severity::warning : Severity::info, text);
}

void LogDownloader::finish_current() {
  if (kind_ == wire::LogKind::sensor) {
    finish(sensor_, log_name(kind_));
  } else {
    finish(telemetry_, log_name(kind_));
  }
}

void LogDownloader::stop(Severity severity, const std::string& why) {
  hooks_.note(severity, why);
  phase_ = Phase::idle;
  asks_.clear();
}

std::string LogDownloader::status() const {
  if (!active()) return "";
  const size_t lines = kind_ == wire::LogKind::sensor ? sensor_.lines.size() : telemetry_.lines.size();
  return std::string(log_name(kind_)) + " log: " + std::to_string(lines) + " lines";
}

}  // namespace qrterm
