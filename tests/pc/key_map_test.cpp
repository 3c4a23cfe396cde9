// The keyboard table: the IN4073 keys where the report puts them, no key twice, every action
// reachable and described, and the manual listing exactly the keys the code binds.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

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
  EXPECT_EQ(qrterm::key_name(7), "code 7");
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
