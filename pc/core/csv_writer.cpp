#include <pc/core/csv_writer.hpp>

namespace qrterm {

std::string csv_field(std::string_view text) {
  // Leading or trailing spaces are quoted too: some readers trim them otherwise.
  const bool quote = text.find_first_of(",\"\r\n") != std::string_view::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

CsvRow& CsvRow::operator<<(std::string_view text) {
  fields_.emplace_back(text);
  return *this;
}

CsvRow& CsvRow::operator<<(int64_t value) {
  fields_.push_back(std::to_string(value));
  return *this;
}

CsvRow& CsvRow::operator<<(uint64_t value) {
  fields_.push_back(std::to_string(value));
  return *this;
}

CsvWriter::CsvWriter(std::ostream& out, const std::vector<std::string>& header) : out_(out), columns_(header.size()) {
  put(header);
}

bool CsvWriter::write(const CsvRow& row) {
  if (row.fields().size() != columns_) return false;
  put(row.fields());
  ++rows_;
  return true;
}

void CsvWriter::put(const std::vector<std::string>& fields) {
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(fields[i]);
  }
  out_ << line << "\r\n";
}

}  // namespace qrterm
