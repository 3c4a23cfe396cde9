// The parameter screen: every row of the parameter table with the console's value, what the QR
// reports, the range, the default and the file's value where it differs; the selected row's unit
// and meaning below; after an autotune flight, the gains flown beside the new ones with their
// figures, under the list (autotune_proposal.hpp).
#include <pc/core/param_file.hpp>
#include <pc/ui/screen_draw.hpp>
#include <pc/ui/screens.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {

void draw_parameter_screen(const Console& console, int top, int rows, int width) {
  const ParameterEditor& editor = console.parameter_editor();
  const ParameterSync& sync = console.parameter_sync();
  put(top, 0, "PARAMETERS", 0, A_BOLD);
  put(top, 11,
      editor.file_name().empty() ? std::string("file (none)")
      : editor.file_exists()     ? "file " + editor.file_name()
                                 : "no file " + editor.file_name() + " yet (written at exit)",
      kDim);
  // 79 columns: names are at most 18 characters, the widest range (-100000..100000) 15.
  put(top + 1, 0, text("%-19s %10s %-10s %-15s %10s %10s", "name", "value", "QR", "range", "default", "file"), 0,
      A_UNDERLINE);

  const int list_top = top + 2;
  const std::vector<std::string> tuned = console.autotune().proposal().lines();
  const int tuned_rows = static_cast<int>(tuned.size());
  const int list_rows = std::max(1, rows - 6 - tuned_rows);
  const int count = static_cast<int>(wire::kParameterCount);
  const int cursor = static_cast<int>(editor.cursor());
  const int first = std::clamp(cursor - list_rows / 2, 0, std::max(0, count - list_rows));
  for (int i = 0; i < list_rows && first + i < count; ++i) {
    const wire::ParameterSpec& spec = wire::kParameterTable[first + i];
    const int32_t wanted = sync.wanted().get(spec.id);
    const ParamStatus status = editor.status(sync, spec.id);
    const std::string qr = status_name(status);
    const std::optional<int32_t> in_file = editor.file_difference(sync, spec.id);
    const std::string range = format_real(spec, spec.min) + ".." + format_real(spec, spec.max);
    // Name and value share their 30 columns: an angle's degrees go between them.
    const std::string line = text("%-30.30s %-10.10s %-15.15s %10.10s %10.10s",
                                  name_and_value(spec, wanted, 30).c_str(), qr.c_str(), range.c_str(),
                                  format_real(spec, spec.default_value).c_str(),
                                  in_file ? format_real(spec, *in_file).c_str() : "");
    const short color = status == ParamStatus::pending   ? kWarning
                        : status == ParamStatus::differs ? kError
                        : in_file                        ? kQr
                                                         : 0;
    put(list_top + i, 0, line, color, first + i == cursor ? A_REVERSE : A_NORMAL);
  }
  // The selected parameter's unit and meaning, on up to two rows.
  const wire::ParameterSpec& selected = editor.selected();
  std::string meaning = std::string(selected.name) + " [" +
                        unit_with_degrees(selected, sync.wanted().get(selected.id)) + "]: " + selected.meaning;
  if (editor.status(sync, selected.id) == ParamStatus::differs)
    meaning = "QR reports " + format_real(selected, *sync.reported(selected.id)) + "; " + meaning;
  const int meaning_row = list_top + list_rows;
  put(meaning_row, 0, meaning.substr(0, static_cast<size_t>(width)), kQr);
  if (meaning.size() > static_cast<size_t>(width))
    put(meaning_row + 1, 0, meaning.substr(static_cast<size_t>(width)), kQr);
  for (int i = 0; i < tuned_rows; ++i) {
    put(meaning_row + 2 + i, 0, tuned[static_cast<size_t>(i)].substr(0, static_cast<size_t>(width)), i == 0 ? kQr : 0,
        i == 1 ? A_UNDERLINE : A_NORMAL);
  }
  put(top + rows - 2, 0,
      std::string("up/down  left/right step  Enter type  = default  ! all default  ^S save  ^O load") +
          (tuned_rows > 1 ? "  ^T tuned  ^R before" : ""),
      kDim);
  draw_prompt_or_log(console, top + rows - 1, width);
}

}  // namespace qrterm
