// telemetry.csv: one row per attitude frame while connected, with the latest of every other
// group and the control the console was sending, all in wire units. Enough to plot a flight with
// gnuplot without a QR log download.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include <common/requests.hpp>
#include <pc/core/csv_writer.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

std::vector<std::string> telemetry_csv_header();
CsvRow telemetry_csv_row(uint32_t time_ms, const TelemetryModel& telemetry, const wire::Control& sent);

}  // namespace qrterm
