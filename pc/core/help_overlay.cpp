#include <pc/core/help_overlay.hpp>

#include <algorithm>

#include <pc/core/action.hpp>
#include <pc/core/key_map.hpp>

namespace qrterm {
namespace {

constexpr const char* kTitle = "keys   Tab: next screen   h or ?: close   any other key acts and closes";

}  // namespace

HelpOverlay help_overlay(int rows, int columns) {
  const std::vector<HelpEntry> entries = help_entries();
  size_t key_width = 0;
  for (const HelpEntry& entry : entries) key_width = std::max(key_width, entry.keys.size());
  const int entry_width = static_cast<int>(key_width + 1 + kActionTextMax);
  const int count = static_cast<int>(entries.size());
  const int room = std::max(1, rows - kHelpTopRow - 1);  // below the title row
  const int column_count = (count + 1) / 2 <= room ? 2 : 3;
  const int per_column = (count + column_count - 1) / column_count;
  const int body_width = column_count * entry_width + (column_count - 1) * kHelpColumnGap;

  HelpOverlay overlay;
  overlay.width = std::min(columns, std::max<int>(body_width, static_cast<int>(std::string(kTitle).size())) + 2);
  overlay.left = std::max(0, (columns - overlay.width) / 2);
  const int height = std::min(rows - kHelpTopRow, per_column + 1);
  overlay.top = kHelpTopRow + std::max(0, (rows - kHelpTopRow - height) / 2);
  const size_t width = static_cast<size_t>(overlay.width);
  overlay.rows.assign(static_cast<size_t>(std::max(0, height)), std::string(width, ' '));
  if (overlay.rows.empty()) return overlay;
  overlay.rows[0].replace(1, std::min(width - 1, std::string(kTitle).size()), kTitle, 0, width - 1);
  const int body_left = (overlay.width - body_width) / 2;
  for (int i = 0; i < count; ++i) {
    const int row = 1 + i % per_column;
    if (row >= height) continue;
    std::string cell = entries[static_cast<size_t>(i)].keys;
    cell.resize(key_width + 1, ' ');
    cell += action_text(entries[static_cast<size_t>(i)].action);
    const int at = body_left + (i / per_column) * (entry_width + kHelpColumnGap);
    if (at < 0 || at >= overlay.width) continue;
    std::string& line = overlay.rows[static_cast<size_t>(row)];
    line.replace(static_cast<size_t>(at), std::min(cell.size(), width - static_cast<size_t>(at)), cell, 0,
                 width - static_cast<size_t>(at));
  }
  return overlay;
}

}  // namespace qrterm
