// QR log lines as CSV rows: the line number, then every field of the record in wire order and in
// wire units (docs/protocol.md section 8), arrays spread over one column each. The column names
// are a table; a test checks each has exactly as many names as the record has values.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include <common/log_records.hpp>
#include <pc/core/csv_writer.hpp>

namespace qrterm {

std::vector<std::string> log_header(const wire::SensorLogRecord&);
std::vector<std::string> log_header(const wire::TelemetryLogRecord&);

// Appends every value a record's field list visits (arrays element by element, enums as numbers).
class CsvFieldVisitor {
 public:
  explicit CsvFieldVisitor(CsvRow& row) : row_(row) {}

  template <class T>
  void operator()(const T& value) {
    if constexpr (std::is_enum_v<T>) {
      row_ << static_cast<uint64_t>(value);
    } else {
      row_ << value;
    }
  }
  template <class T, size_t N>
  void operator()(const T (&values)[N]) {
    for (const T& value : values) (*this)(value);
  }

 private:
  CsvRow& row_;
};

template <class Record>
CsvRow log_row(const Record& record) {
  CsvRow row;
  row << record.line;
  CsvFieldVisitor visitor(row);
  Record::fields(record, visitor);
  return row;
}

}  // namespace qrterm
