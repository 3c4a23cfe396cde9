#include <pc/core/telemetry_csv.hpp>

#include <pc/core/log_csv.hpp>

namespace qrterm {
namespace {

// A group not heard yet is written as empty fields, not as zeros that would look like data.
template <class Group>
void put(CsvRow& row, const std::optional<Group>& group) {
  if (group) {
    CsvFieldVisitor visitor(row);
    Group::fields(*group, visitor);
  } else {
    CsvRow empty;
    CsvFieldVisitor visitor(empty);
    const Group blank{};
    Group::fields(blank, visitor);
    for (size_t i = 0; i < empty.fields().size(); ++i) row << "";
  }
}

}  // namespace

std::vector<std::string> telemetry_csv_header() {
  return {"pc_time_ms",
          "tick",
          "mode",
          "flags",
          "phi",
          "theta",
          "psi",
          "p",
          "q",
          "r",
          "engine_front",
          "engine_right",
          "engine_back",
          "engine_left",
          "sp_lift",
          "sp_roll",
          "sp_pitch",
          "sp_yaw_rate",
          "battery_mv",
          "cpu_load",
          "loop_time_us",
          "deadline_misses",
          "qr_frames_ok",
          "qr_check_failures",
          "qr_unknown_types",
          "qr_bytes_skipped",
          "qr_rx_overruns",
          "ctl_lift",
          "ctl_roll",
          "ctl_pitch",
          "ctl_yaw",
          "height_mm",
          "climb_mm_s",
          "height_flags",
          "hover_lift"};
}

CsvRow telemetry_csv_row(uint32_t time_ms, const TelemetryModel& telemetry, const wire::Control& sent) {
  CsvRow row;
  row << time_ms;
  put(row, telemetry.attitude);
  put(row, telemetry.rates);
  put(row, telemetry.engines);
  put(row, telemetry.setpoints);
  put(row, telemetry.system);
  put(row, telemetry.qr_link);
  put(row, std::optional<wire::Control>(sent));
  put(row, telemetry.height);  // last: the columns before it stay where earlier files had them
  return row;
}

}  // namespace qrterm
