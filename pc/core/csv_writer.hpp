// Comma-separated values as RFC 4180 reads them: a header row, then rows of the same number of
// fields; a field with a comma, a quote or a line break is quoted, quotes doubled. Every file the
// console writes for a spreadsheet or gnuplot goes through here.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace qrterm {

class CsvRow {
 public:
  CsvRow& operator<<(std::string_view text);
  CsvRow& operator<<(const char* text) { return *this << std::string_view(text); }
  CsvRow& operator<<(const std::string& text) { return *this << std::string_view(text); }
  CsvRow& operator<<(int64_t value);
  CsvRow& operator<<(uint64_t value);
  CsvRow& operator<<(int32_t value) { return *this << int64_t{value}; }
  CsvRow& operator<<(uint32_t value) { return *this << uint64_t{value}; }
  CsvRow& operator<<(int16_t value) { return *this << int64_t{value}; }
  CsvRow& operator<<(uint16_t value) { return *this << uint64_t{value}; }
  CsvRow& operator<<(uint8_t value) { return *this << uint64_t{value}; }

  const std::vector<std::string>& fields() const { return fields_; }

 private:
  std::vector<std::string> fields_;
};

class CsvWriter {
 public:
  // Writes the header row at once.
  CsvWriter(std::ostream& out, const std::vector<std::string>& header);

  // False (and nothing written) when the row has another number of fields than the header: a
  // short row would shift every later column under the wrong name.
  bool write(const CsvRow& row);

  size_t rows() const { return rows_; }
  size_t columns() const { return columns_; }

 private:
  void put(const std::vector<std::string>& fields);

  std::ostream& out_;
  size_t columns_;
  size_t rows_ = 0;
};

// One field as it appears in the file: quoted when it must be.
std::string csv_field(std::string_view text);

}  // namespace qrterm
