#include <pc/core/observable_catalog.hpp>

#include <cmath>

namespace qrterm {

bool ObservableRow::complete() const {
  if (!have_info || last_part < 0) return false;
  const unsigned needed = (1u << (last_part + 1)) - 1u;
  return (parts & needed) == needed && !name.empty();
}

double ObservableRow::value(int16_t bits) const {
  const double raw = type == wire::ObservableType::u16 ? static_cast<double>(static_cast<uint16_t>(bits))
                                                       : static_cast<double>(bits);
  return raw * std::pow(10.0, scale);
}

ObservableRow& ObservableCatalog::slot(uint8_t id) {
  if (rows_.size() <= id) rows_.resize(size_t{id} + 1);
  return rows_[id];
}

void ObservableCatalog::on(const wire::ObservableInfo& info) {
  count_ = info.count;
  control_hz_ = info.control_hz;
  ObservableRow& row = slot(info.id);
  row.have_info = true;
  row.type = info.type;
  row.scale = info.scale;
}

void ObservableCatalog::on(const wire::ObservableText& piece) {
  ObservableRow& row = slot(piece.id);
  const size_t at = size_t{piece.part} * wire::kObservableTextPartChars;
  if (row.text.size() < at + wire::kObservableTextPartChars) row.text.resize(at + wire::kObservableTextPartChars, '\0');
  bool ended = false;  // the part holding a NUL is the last (docs/protocol.md section 13.1)
  for (size_t i = 0; i < wire::kObservableTextPartChars; ++i) {
    row.text[at + i] = piece.text[i];
    ended = ended || piece.text[i] == '\0';
  }
  row.parts = static_cast<uint8_t>(row.parts | (1u << piece.part));
  if (ended) row.last_part = static_cast<int8_t>(piece.part);
  // "name unit": split at the first space once the text is whole.
  const std::string whole = row.text.substr(0, row.text.find('\0'));
  const size_t space = whole.find(' ');
  row.name = space == std::string::npos ? whole : whole.substr(0, space);
  row.unit = space == std::string::npos ? "" : whole.substr(space + 1);
}

size_t ObservableCatalog::complete_rows() const {
  size_t n = 0;
  for (size_t id = 0; id < rows_.size() && id < count_; ++id) n += rows_[id].complete() ? 1 : 0;
  return n;
}

const ObservableRow* ObservableCatalog::row(uint8_t id) const {
  return id < rows_.size() && id < count_ && rows_[id].complete() ? &rows_[id] : nullptr;
}

std::optional<uint8_t> ObservableCatalog::find(const std::string& name) const {
  for (size_t id = 0; id < rows_.size() && id < count_; ++id) {
    if (rows_[id].complete() && rows_[id].name == name) return static_cast<uint8_t>(id);
  }
  return std::nullopt;
}

std::vector<std::string> ObservableCatalog::names_starting(const std::string& prefix) const {
  std::vector<std::string> names;
  for (size_t id = 0; id < rows_.size() && id < count_; ++id) {
    if (rows_[id].complete() && rows_[id].name.rfind(prefix, 0) == 0) names.push_back(rows_[id].name);
  }
  return names;
}

}  // namespace qrterm
