#include <pc/core/recordings.hpp>

#include <pc/core/hex_log.hpp>
#include <pc/core/telemetry_csv.hpp>

namespace qrterm {

Recordings::Recordings(ConsoleFiles files, size_t rx_hex_part_bytes, Note note)
    : files_(std::move(files)), note_(std::move(note)), rx_hex_part_bytes_(rx_hex_part_bytes) {
  if (files_.telemetry_csv != nullptr) telemetry_csv_.emplace(*files_.telemetry_csv, telemetry_csv_header());
}

void Recordings::received(uint32_t time_ms, const uint8_t* data, size_t count) {
  if (files_.rx_hex == nullptr || count == 0) return;
  const std::string line = hex_line(time_ms, data, count);
  if (rx_hex_bytes_ + line.size() > rx_hex_part_bytes_ && files_.restart_rx_hex) {
    files_.rx_hex = files_.restart_rx_hex();
    rx_hex_bytes_ = 0;
    note_(Severity::info, files_.rx_hex != nullptr
                              ? std::string("rx.hex full: the part before is ") + kRxHexPrevious + " now"
                              : std::string("rx.hex full and cannot start again: received bytes no longer recorded"));
    if (files_.rx_hex == nullptr) return;
  }
  *files_.rx_hex << line;
  rx_hex_bytes_ += line.size();
  if (!files_.rx_hex->good()) file_failed(files_.rx_hex, "rx.hex", "rx.partial.hex");
}

void Recordings::telemetry_row(uint32_t time_ms, const TelemetryModel& telemetry, const wire::Control& sent) {
  if (!telemetry_csv_) return;
  telemetry_csv_->write(telemetry_csv_row(time_ms, telemetry, sent));
  if (!files_.telemetry_csv->good()) {
    telemetry_csv_.reset();
    file_failed(files_.telemetry_csv, "telemetry.csv", "telemetry.partial.csv");
  }
}

std::unique_ptr<std::ostream> Recordings::open(const std::string& name) const {
  return files_.open ? files_.open(name) : nullptr;
}

bool Recordings::rename(const std::string& from, const std::string& to) const {
  return files_.rename && files_.rename(from, to);
}

void Recordings::file_failed(std::ostream*& file, const char* name, const char* partial_name) {
  file = nullptr;
  const bool renamed = rename(name, partial_name);
  note_(Severity::error, std::string("cannot write ") + name + " (disk full or log folder read-only): it ends here" +
                             (renamed ? std::string(", renamed ") + partial_name : std::string(", and is partial")));
}

}  // namespace qrterm
