// The QR's observable table as the console learns it over the wire (observable_info and
// observable_text, docs/protocol.md section 13.1): a row is usable once its numbers and its whole
// "name unit" text have arrived. The console asks for the table at connect and again while rows
// are missing; it never assumes its own copy of common/ matches the firmware's.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <optional>
#include <string>
#include <vector>

#include <common/observable_messages.hpp>

namespace qrterm {

struct ObservableRow {
  bool have_info = false;
  wire::ObservableType type = wire::ObservableType::i16;
  int8_t scale = 0;
  uint8_t parts = 0;      // bit k: text part k arrived
  int8_t last_part = -1;  // the part that ended the text (held a NUL, or part 3); -1: not yet seen
  std::string text;       // raw characters of the parts, NUL-padded
  std::string name;
  std::string unit;

  bool complete() const;
  // The value in the row's unit of a sample's 16 bits.
  double value(int16_t bits) const;
};

class ObservableCatalog {
 public:
  void on(const wire::ObservableInfo& info);
  void on(const wire::ObservableText& text);
  void clear() { *this = ObservableCatalog{}; }

  size_t count() const { return count_; }  // rows the QR says it has; 0: not heard yet
  size_t complete_rows() const;
  bool complete() const { return count_ > 0 && complete_rows() == count_; }
  uint16_t control_hz() const { return control_hz_; }
  const ObservableRow* row(uint8_t id) const;
  std::optional<uint8_t> find(const std::string& name) const;
  // Names of the complete rows starting with `prefix`, in id order.
  std::vector<std::string> names_starting(const std::string& prefix) const;

 private:
  ObservableRow& slot(uint8_t id);

  size_t count_ = 0;
  uint16_t control_hz_ = 0;
  std::vector<ObservableRow> rows_;
};

}  // namespace qrterm
