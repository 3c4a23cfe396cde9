// The parameter screen's logic: a cursor over the parameter table, a step up or down, a typed
// value, back to the default, and named parameter files saved and loaded; every change goes to the
// QR through the ParameterSync (one param_set at a time, then a read-back). What a row shows: the
// value the console wants, what the QR last reported, whether it is on its way, and how it differs
// from the file the values came from.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <optional>
#include <string>

#include <common/parameter_table.hpp>
#include <pc/core/parameter_sync.hpp>

namespace qrterm {

enum class ParamStatus : uint8_t {
  pending,    // sent (or queued), not answered yet
  read_back,  // the QR reports the value the console wants
  differs,    // the QR reports another value (it refused, or nothing was sent yet)
  unknown,    // the QR has not reported it
};

const char* status_name(ParamStatus status);

// An angle parameter (unit mrad) in degrees; nothing for any other. A pilot thinks in degrees: one
// who wanted a 45 deg stick found that full stick asks for max_tilt_mrad, at most 698 mrad, 40 deg.
std::optional<double> degrees_of(const wire::ParameterSpec& spec, int32_t raw);

// A row's name and value columns in `width` characters: the name at the left, the value at the
// right (so the values line up), and an angle's degrees just left of its value, where they fit:
// "max_tilt_mrad (30.0 deg)  524".
std::string name_and_value(const wire::ParameterSpec& spec, int32_t raw, size_t width);

// The unit as the selected row's meaning line names it: "mrad", or for an angle with the value in
// degrees, "mrad, now 30.0 deg".
std::string unit_with_degrees(const wire::ParameterSpec& spec, int32_t raw);

class ParameterEditor {
 public:
  // `file_exists`: the values came from that file; false when there was none (the defaults), and
  // then no row shows a file value until a file is written or loaded.
  explicit ParameterEditor(const wire::ParameterValues& file_values, std::string file_name, bool file_exists = true)
      : file_values_(file_values), file_name_(std::move(file_name)), file_exists_(file_exists) {}

  size_t cursor() const { return cursor_; }
  const wire::ParameterSpec& selected() const { return wire::kParameterTable[cursor_]; }
  void move(int rows);

  ParamStatus status(const ParameterSync& sync, wire::ParamId id) const;
  // The value the file holds, or nothing when the console's value is the file's or there is no
  // file.
  std::optional<int32_t> file_difference(const ParameterSync& sync, wire::ParamId id) const;
  const std::string& file_name() const { return file_name_; }
  bool file_exists() const { return file_exists_; }
  // One parameter written into the file at `path` by someone else (the orientation check): the
  // file column follows when it is this file.
  void file_written(const std::string& path, wire::ParamId id, int32_t raw);

  // The selected parameter one step up (+1) or down (-1): the gain keys' step where a key has one
  // (C1 and C2 double and halve), else a hundredth of its range.
  void step(ParameterSync& sync, int direction) const;
  // A value typed in the parameter's unit ("5.75"): an error text, or empty when sent.
  std::string set_typed(ParameterSync& sync, const std::string& text) const;
  void reset_default(ParameterSync& sync) const;
  // Every parameter back to its default (what differs is sent); how many changed.
  size_t reset_all_defaults(ParameterSync& sync) const;

  // Named parameter files, in parameter-file format: an error text, or empty.
  std::string save(const ParameterSync& sync, const std::string& path);
  std::string load(ParameterSync& sync, const std::string& path);

 private:
  wire::ParameterValues file_values_;
  std::string file_name_;
  bool file_exists_;
  size_t cursor_ = 0;
};

}  // namespace qrterm
