// The keyboard table: the IN4073 keys where the report puts them, no key twice, every action
// reachable and described, and the manual listing exactly the keys the code binds.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <pc/core/help_overlay.hpp>
#include <pc/core/key_map.hpp>
#include <pc/core/pilot_controls.hpp>

namespace {

using qrterm::Action;
using qrterm::action_for;

TEST(KeyMap, In4073KeysAreWhereTheReportPutsThem) {
  const std::pair<qrterm::Key, Action> expected[] = {
      {qrterm::kKeyEscape, Action::abort},
      {'0', Action::mode_safe},
      {'1', Action::mode_panic},
      {'2', Action::mode_manual},
      {'3', Action::mode_calibration},
      {'4', Action::mode_yaw_control},
      {'5', Action::mode_full_control},
      {'a', Action::lift_up},
      {'z', Action::lift_down},
      {qrterm::kKeyLeft, Action::roll_left},
      {qrterm::kKeyRight, Action::roll_right},
      {qrterm::kKeyUp, Action::pitch_down},
      {qrterm::kKeyDown, Action::pitch_up},
      {'q', Action::yaw_left},
      {'w', Action::yaw_right},
      {'u', Action::yaw_p_up},
      {'j', Action::yaw_p_down},
      {'i', Action::p1_up},
      {'k', Action::p1_down},
      {'o', Action::p2_up},
      {'l', Action::p2_down},
      {'x', Action::exit},
      {'h', Action::help},
      {'?', Action::help},
  };
  for (const auto& [key, action] : expected) EXPECT_EQ(action_for(key), action) << qrterm::key_name(key);
}

TEST(KeyMap, NoKeyIsBoundTwice) {
  std::set<qrterm::Key> keys;
  for (const qrterm::KeyBinding& binding : qrterm::kKeyMap) {
    EXPECT_TRUE(keys.insert(binding.key).second) << qrterm::key_name(binding.key);
    EXPECT_FALSE(binding.key >= 'A' && binding.key <= 'Z') << "capitals are folded to small letters";
  }
}

TEST(KeyMap, EveryActionHasAKeyAndAShortText) {
  for (const qrterm::ActionSpec& spec : qrterm::kActions) {
    bool bound = false;
    for (const qrterm::KeyBinding& binding : qrterm::kKeyMap) bound = bound || binding.action == spec.action;
    EXPECT_TRUE(bound) << spec.text;
    EXPECT_LE(std::string(spec.text).size(), qrterm::kActionTextMax) << spec.text;
  }
  for (const qrterm::KeyBinding& binding : qrterm::kKeyMap) {
    EXPECT_STRNE(qrterm::action_text(binding.action), "") << qrterm::key_name(binding.key);
  }
}

TEST(KeyMap, CapitalLettersActLikeSmallOnesAndUnboundKeysDoNothing) {
  EXPECT_EQ(action_for('X'), Action::exit);
  EXPECT_EQ(action_for('A'), Action::lift_up);
  EXPECT_EQ(action_for('%'), Action::none);
  EXPECT_EQ(action_for(qrterm::kKeyNone), Action::none);
}

TEST(KeyMap, KeysHaveNamesForTheHelp) {
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyEscape), "ESC");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyUp), "up");
  EXPECT_EQ(qrterm::key_name('a'), "a");
  EXPECT_EQ(qrterm::key_name(7), "^G") << "a control key as a terminal user writes it";
  EXPECT_EQ(qrterm::key_name(0x2000), "code 8192") << "a key without a name still says what it is";
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyEnter), "Enter") << "not \"key 13\"";
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyTab), "Tab");
}

TEST(KeyMap, TrimsStepAndStayInRange) {
  qrterm::PilotControls controls;
  for (int i = 0; i < 200; ++i) controls.apply(Action::lift_up);
  EXPECT_EQ(controls.control().lift, 1000);
  for (int i = 0; i < 300; ++i) controls.apply(Action::lift_down);
  EXPECT_EQ(controls.control().lift, 0);
  for (int i = 0; i < 300; ++i) controls.apply(Action::roll_left);
  EXPECT_EQ(controls.control().roll, -1000);
  controls.set_joystick({0, -500, 0, 0});
  EXPECT_EQ(controls.control().roll, -1000) << "the sum is clamped too";
  EXPECT_TRUE(controls.apply(Action::trims_center));
  EXPECT_EQ(controls.control().roll, -500);
  EXPECT_FALSE(controls.apply(Action::exit));
}

// 53 presses of a to reach a hover was too many for a newcomer: PgUp takes ten steps at once, and
// both ends of the range still hold.
TEST(KeyMap, CoarseLiftKeysReachAHoverInAFewPresses) {
  EXPECT_EQ(action_for(qrterm::kKeyPageUp), Action::lift_up_coarse);
  EXPECT_EQ(action_for(qrterm::kKeyPageDown), Action::lift_down_coarse);
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyPageUp), "PgUp");
  qrterm::PilotControls controls;
  for (int i = 0; i < 5; ++i) controls.apply(Action::lift_up_coarse);
  for (int i = 0; i < 3; ++i) controls.apply(Action::lift_up);
  EXPECT_EQ(controls.control().lift, 5 * qrterm::kLiftCoarseStep + 3 * qrterm::kLiftTrimStep);
  EXPECT_EQ(controls.control().lift, 530) << "eight presses, not 53";
  for (int i = 0; i < 20; ++i) controls.apply(Action::lift_up_coarse);
  EXPECT_EQ(controls.control().lift, 1000);
  for (int i = 0; i < 20; ++i) controls.apply(Action::lift_down_coarse);
  EXPECT_EQ(controls.control().lift, 0);
}

// The help overlay at 80x24 shows every key: keys that do the same share an entry, and each key is
// in exactly one.
TEST(KeyMap, TheHelpOverlayHoldsEveryKeyAt80x24) {
  const std::vector<qrterm::HelpEntry> entries = qrterm::help_entries();
  EXPECT_LE(entries.size(), qrterm::kHelpEntriesAt80x24);
  std::map<std::string, Action> shown;  // key name -> the action its entry says
  for (const qrterm::HelpEntry& entry : entries) {
    std::istringstream keys(entry.keys);
    for (std::string key; keys >> key;) EXPECT_TRUE(shown.emplace(key, entry.action).second) << key << " twice";
  }
  EXPECT_EQ(shown.size(), qrterm::kKeyBindingCount);
  for (const qrterm::KeyBinding& binding : qrterm::kKeyMap) {
    const auto it = shown.find(qrterm::key_name(binding.key));
    ASSERT_NE(it, shown.end()) << qrterm::key_name(binding.key);
    EXPECT_EQ(it->second, binding.action) << qrterm::key_name(binding.key);
  }
  EXPECT_EQ(entries[1].keys, "x ^C");
  EXPECT_EQ(entries.back().keys, "h ?");
}

// F1 and Delete showed as "key code 265/330": the common keys no screen binds have names, so
// "key F1 does nothing" says which key it was.
TEST(KeyMap, UnboundCommonKeysHaveNames) {
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyF1), "F1");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyF1 + 11), "F12");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyDelete), "Delete");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyInsert), "Insert");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyEnd), "End");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyBackTab), "Shift+Tab");
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyBackspace), "Backspace");
  for (qrterm::Key f = qrterm::kKeyF1; f < qrterm::kKeyF1 + qrterm::kFunctionKeys; ++f)
    EXPECT_EQ(qrterm::key_name(f).rfind("F", 0), 0u) << f;
}

// At 80x24 the help overlay's three columns ran together (an entry's text up against the next
// column's key) and Tab was nowhere. Each entry now stands whole in its column with two spaces
// before the next, and the title names Tab; the rows above it (mode, link, engines) stay clear.
TEST(HelpOverlay, EveryEntryStandsApartAt80x24AndTabIsNamed) {
  const qrterm::HelpOverlay overlay = qrterm::help_overlay(24, 80);
  EXPECT_GE(overlay.top, qrterm::kHelpTopRow);
  EXPECT_LE(overlay.top + static_cast<int>(overlay.rows.size()), 24);
  EXPECT_LE(overlay.left + overlay.width, 80);
  ASSERT_FALSE(overlay.rows.empty());
  EXPECT_NE(overlay.rows[0].find("Tab: next screen"), std::string::npos) << overlay.rows[0];
  for (const std::string& row : overlay.rows) EXPECT_EQ(row.size(), static_cast<size_t>(overlay.width));
  for (const qrterm::HelpEntry& entry : qrterm::help_entries()) {
    // "x ^C  exit (QR to safe)": the keys, padded, then the text, and then two spaces or the row's end.
    std::string cell = entry.keys;
    cell.resize(5 + 1, ' ');
    cell += qrterm::action_text(entry.action);
    bool found = false;
    for (size_t r = 1; r < overlay.rows.size() && !found; ++r) {
      const size_t at = overlay.rows[r].find(cell);
      if (at == std::string::npos) continue;
      found = true;
      const std::string after = overlay.rows[r].substr(at + cell.size(), 2);
      EXPECT_TRUE(after.find_first_not_of(' ') == std::string::npos) << "\"" << cell << "\" runs into \"" << after;
      if (at > 0) EXPECT_EQ(overlay.rows[r][at - 1], ' ') << cell;
    }
    EXPECT_TRUE(found) << cell;
  }
  // A taller terminal: two columns, the same entries.
  const qrterm::HelpOverlay tall = qrterm::help_overlay(40, 80);
  EXPECT_EQ(tall.rows.size(), (qrterm::help_entries().size() + 1) / 2 + 1);
}

// docs/console.md has a table of keys, rows like "| `a` | ... |": it must list every bound key
// and no other.
TEST(KeyMap, TheManualListsExactlyTheBoundKeys) {
  std::ifstream in(QR_CONSOLE_DOC);
  ASSERT_TRUE(in) << QR_CONSOLE_DOC;
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const size_t start = doc.find("## Keys");
  ASSERT_NE(start, std::string::npos);
  const size_t end = doc.find("\n## ", start + 1);
  const std::string section = doc.substr(start, end - start);
  std::set<std::string> listed;
  const std::regex row(R"(\n\| `([^`]+)` \|)");
  for (std::sregex_iterator it(section.begin(), section.end(), row), stop; it != stop; ++it) listed.insert((*it)[1]);
  std::set<std::string> bound;
  for (const qrterm::KeyBinding& binding : qrterm::kKeyMap) bound.insert(qrterm::key_name(binding.key));
  EXPECT_EQ(listed, bound);
}

}  // namespace
