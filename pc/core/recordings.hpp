// What the session records in its log folder as it goes (docs/console.md "Files"): rx.hex, every
// byte received, and telemetry.csv, a row per attitude frame. A file that cannot be written (disk
// full, folder gone read-only) is written no more, named partial and said once: a file cut short
// never passes for whole. The others that write in the folder (the log downloads, the stream CSVs)
// open and rename their files through here.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <common/requests.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/csv_writer.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

// rx.hex grows by some 70 MB an hour of telemetry: past this size it starts again, the part before
// kept as rx.hex.1, so a session holds at most twice this (16 MiB; with the session folders kept,
// log_retention.hpp, the disk holds a bounded amount) and the newest bytes are always there.
inline constexpr size_t kRxHexPartBytes = 8u << 20;
inline constexpr const char* kRxHexPrevious = "rx.hex.1";

// Where the console writes; any may be absent.
struct ConsoleFiles {
  std::ostream* rx_hex = nullptr;
  // Moves the full rx.hex aside and gives a fresh one (null: recording stops).
  std::function<std::ostream*()> restart_rx_hex;
  std::ostream* telemetry_csv = nullptr;
  std::function<std::unique_ptr<std::ostream>(const std::string& name)> open;  // a new file in the log folder
  // Renames a file of the log folder (false when it could not): a file cut short by a full disk
  // or a folder gone read-only is named partial, never left to pass for whole.
  std::function<bool(const std::string& from, const std::string& to)> rename;
};

class Recordings {
 public:
  using Note = std::function<void(Severity, const std::string&)>;

  Recordings(ConsoleFiles files, size_t rx_hex_part_bytes, Note note);

  // Bytes from the QR, `time_ms` since the console started.
  void received(uint32_t time_ms, const uint8_t* data, size_t count);
  // An attitude frame came: a row of the telemetry as it stands and the control last sent.
  void telemetry_row(uint32_t time_ms, const TelemetryModel& telemetry, const wire::Control& sent);

  // A new file in the log folder (null: none could be made).
  std::unique_ptr<std::ostream> open(const std::string& name) const;
  bool rename(const std::string& from, const std::string& to) const;

 private:
  void file_failed(std::ostream*& file, const char* name, const char* partial_name);

  ConsoleFiles files_;
  Note note_;
  size_t rx_hex_part_bytes_;
  size_t rx_hex_bytes_ = 0;  // in the rx.hex being written
  std::optional<CsvWriter> telemetry_csv_;
};

}  // namespace qrterm
