// The joystick wizard's logic (pc/core/joystick_wizard.*) driven as a pilot would drive it: the
// driver's events for a stick of a given layout, Enter between the steps, the time for the rest.
#include <gtest/gtest.h>

#include <algorithm>

#include <pc/core/joystick_map.hpp>
#include <pc/core/joystick_reader.hpp>
#include <pc/core/joystick_wizard.hpp>

namespace {

using qrterm::JoystickMap;
using qrterm::WizardStep;

constexpr int16_t kFull = 32767;

js_event axis_event(uint8_t axis, int16_t value, uint8_t flags = 0) {
  return js_event{0, value, static_cast<uint8_t>(JS_EVENT_AXIS | flags), axis};
}
js_event button_event(uint8_t button, int16_t value, uint8_t flags = 0) {
  return js_event{0, value, static_cast<uint8_t>(JS_EVENT_BUTTON | flags), button};
}

// A joystick's layout: which axis each control is, the raw value it reads at the end the pilot
// is asked for first (right, back, twist right, throttle open), and its fire button.
struct Stick {
  uint8_t roll = 0;
  uint8_t pitch = 1;
  uint8_t yaw = 2;
  uint8_t lift = 3;
  int16_t right = kFull;
  int16_t back = kFull;
  int16_t twist_right = kFull;
  int16_t open = -kFull;  // closed is the other end
  uint8_t fire = 0;
};

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

class JoystickWizard : public ::testing::Test {
 protected:
  // What the driver reports at open: sticks centred, throttle closed, buttons up.
  void plug_in(const Stick& stick) {
    for (uint8_t axis : {stick.roll, stick.pitch, stick.yaw}) wizard.event(axis_event(axis, 0, JS_EVENT_INIT));
    wizard.event(axis_event(stick.lift, static_cast<int16_t>(-stick.open), JS_EVENT_INIT));
    for (uint8_t button = 0; button < 8; ++button) wizard.event(button_event(button, 0, JS_EVENT_INIT));
  }
  // Enter, the events while keeping still, a second.
  void rest(const std::vector<js_event>& noise = {}) {
    wizard.next(now);
    for (const js_event& e : noise) wizard.event(e);
    now += qrterm::JoystickWizard::kRestMs;
    wizard.tick(now);
  }
  // To `first`, to the other end, back to `rest_at`; Enter.
  void sweep(uint8_t axis, int16_t first, int16_t rest_at = 0) {
    for (int16_t value : {static_cast<int16_t>(first / 2), first, static_cast<int16_t>(-first), rest_at})
      wizard.event(axis_event(axis, value));
    wizard.next(now);
  }
  void lift_sweep(const Stick& stick) {
    wizard.event(axis_event(stick.lift, 0));
    wizard.event(axis_event(stick.lift, stick.open));
    wizard.event(axis_event(stick.lift, static_cast<int16_t>(-stick.open)));
    wizard.next(now);
  }
  void fire(const Stick& stick) {
    wizard.event(button_event(stick.fire, 1));
    wizard.event(button_event(stick.fire, 0));
  }
  void run(const Stick& stick) {
    plug_in(stick);
    rest();
    sweep(stick.roll, stick.right);
    sweep(stick.pitch, stick.back);
    sweep(stick.yaw, stick.twist_right);
    lift_sweep(stick);
    fire(stick);
  }

  qrterm::JoystickWizard wizard;
  uint32_t now = 5000;
};

TEST_F(JoystickWizard, FindsEachControlsAxisAndTheFireButton) {
  Stick stick;
  stick.roll = 2;
  stick.pitch = 0;
  stick.yaw = 5;
  stick.lift = 1;
  stick.fire = 3;
  run(stick);
  ASSERT_EQ(wizard.step(), WizardStep::review) << "the fire button ends the steps";
  EXPECT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  const JoystickMap& map = wizard.map();
  EXPECT_EQ(map.roll.axis, 2);
  EXPECT_EQ(map.pitch.axis, 0);
  EXPECT_EQ(map.yaw.axis, 5);
  EXPECT_EQ(map.lift.axis, 1);
  EXPECT_FALSE(map.roll.invert);
  EXPECT_FALSE(map.pitch.invert);
  EXPECT_FALSE(map.yaw.invert);
  EXPECT_EQ(map.abort_button, 3);
  EXPECT_EQ(wizard.found(WizardStep::roll).min, -kFull);
  EXPECT_EQ(wizard.found(WizardStep::roll).max, kFull);
  EXPECT_EQ(wizard.summary(WizardStep::roll), "axis 2, -32767..32767, right reads +");
}

TEST_F(JoystickWizard, FindsAnInvertedAxis) {
  Stick stick;
  stick.back = -kFull;  // this stick reads pulled back as negative
  stick.right = -kFull;
  run(stick);
  ASSERT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  const JoystickMap& map = wizard.map();
  EXPECT_TRUE(map.pitch.invert);
  EXPECT_TRUE(map.roll.invert);
  EXPECT_FALSE(map.yaw.invert);
  EXPECT_EQ(map.stick(map.pitch, -kFull), 1000) << "pulled back is positive pitch";
  EXPECT_EQ(map.stick(map.roll, -kFull), 1000) << "right is positive roll";
  EXPECT_NE(wizard.summary(WizardStep::pitch).find("back reads - (inverted)"), std::string::npos);
}

TEST_F(JoystickWizard, FindsAThrottleWhoseIdleIsFullPositive) {
  Stick stick;
  stick.open = -kFull;  // closed at +32767, as most levers read
  run(stick);
  ASSERT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  const JoystickMap& map = wizard.map();
  EXPECT_TRUE(map.lift.invert);
  EXPECT_EQ(map.lift_of(kFull), 0) << "idle is no lift";
  EXPECT_EQ(map.lift_of(-kFull), 1000) << "open is full lift";
}

TEST_F(JoystickWizard, FindsAThrottleWhoseIdleIsFullNegative) {
  Stick stick;
  stick.open = kFull;
  run(stick);
  ASSERT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  EXPECT_FALSE(wizard.map().lift.invert);
  EXPECT_EQ(wizard.map().lift_of(-kFull), 0);
  EXPECT_EQ(wizard.map().lift_of(kFull), 1000);
}

TEST_F(JoystickWizard, RefusesAControlNeverMoved) {
  const Stick stick;
  plug_in(stick);
  rest();
  sweep(stick.roll, stick.right);
  sweep(stick.pitch, stick.back);
  wizard.event(axis_event(stick.yaw, 20000));  // nudged well past a quarter, not through half its range
  wizard.event(axis_event(stick.yaw, 0));
  wizard.next(now);
  lift_sweep(stick);
  fire(stick);
  ASSERT_EQ(wizard.step(), WizardStep::review);
  ASSERT_EQ(wizard.errors().size(), 1u);
  EXPECT_EQ(wizard.errors()[0],
            "yaw: no axis moved through half its range or more (twist the stick fully right and "
            "left in its step)");
  EXPECT_EQ(wizard.summary(WizardStep::yaw), "nothing moved through half its range");
}

TEST_F(JoystickWizard, RefusesTwoControlsOnOneAxis) {
  const Stick stick;
  plug_in(stick);
  rest();
  sweep(stick.roll, stick.right);
  sweep(stick.pitch, stick.back);
  sweep(stick.roll, stick.right);  // the yaw step, but the stick moved right and left again
  lift_sweep(stick);
  fire(stick);
  ASSERT_EQ(wizard.errors().size(), 1u);
  EXPECT_EQ(wizard.errors()[0], "roll and yaw both moved axis 0 most (in each step move only the control it asks for)");
}

TEST_F(JoystickWizard, TheDeadbandComesFromTheNoiseWhileResting) {
  const Stick stick;
  plug_in(stick);
  wizard.event(axis_event(stick.roll, 20000));  // still letting go: before Enter, not counted
  wizard.event(axis_event(stick.roll, 300));
  rest({axis_event(stick.roll, -400), axis_event(stick.pitch, -900), axis_event(stick.pitch, 200),
        axis_event(7, 30000)});               // an axis no control uses: not counted
  wizard.event(axis_event(stick.yaw, 5000));  // after the rest (the roll step has begun): not counted
  sweep(stick.roll, stick.right);
  sweep(stick.pitch, stick.back);
  sweep(stick.yaw, stick.twist_right);
  lift_sweep(stick);
  fire(stick);
  ASSERT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  EXPECT_EQ(*wizard.found(WizardStep::roll).rest_permille, 13) << "400 of 32767, rounded up";
  EXPECT_EQ(*wizard.found(WizardStep::pitch).rest_permille, 28) << "900 of 32767, rounded up";
  EXPECT_EQ(*wizard.found(WizardStep::yaw).rest_permille, 0);
  EXPECT_EQ(*wizard.found(WizardStep::lift).rest_permille, 0);
  const JoystickMap& map = wizard.map();
  EXPECT_EQ(map.deadband_permille, 56) << "twice the highest reading at rest";
  EXPECT_EQ(wizard.deadband_reason(), "twice the 28 per mille pitch read at rest");
  for (const int16_t resting : {int16_t{-400}, int16_t{300}, int16_t{-900}, int16_t{200}}) {
    EXPECT_EQ(map.stick(map.pitch, resting), 0) << resting;
    EXPECT_EQ(map.stick(map.roll, resting), 0) << resting;
  }
  EXPECT_GT(map.stick(map.pitch, 4000), 0) << "past the band the stick counts";
}

TEST_F(JoystickWizard, AStillStickGetsTheSmallestDeadband) {
  run(Stick{});
  ASSERT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  EXPECT_EQ(wizard.map().deadband_permille, 20);
  EXPECT_EQ(wizard.deadband_reason(), "the least, 20: no control read more than 10 per mille at rest");
}

TEST_F(JoystickWizard, RefusesControlsNotAtRestWhileResting) {
  const Stick stick;
  plug_in(stick);
  wizard.event(axis_event(stick.lift, 0));  // throttle half open
  rest({axis_event(stick.roll, 12000)});    // a hand on the stick
  wizard.event(axis_event(stick.lift, static_cast<int16_t>(-stick.open)));
  sweep(stick.roll, stick.right);
  sweep(stick.pitch, stick.back);
  sweep(stick.yaw, stick.twist_right);
  lift_sweep(stick);
  fire(stick);
  ASSERT_EQ(wizard.errors().size(), 2u);
  EXPECT_EQ(wizard.errors()[0],
            "roll: axis 0 read 367 per mille at the rest, more than 250 (let go of the stick while resting)");
  EXPECT_EQ(wizard.errors()[1],
            "lift: axis 3 read 500 per mille at the rest, more than 250 (close the throttle while resting)");
}

TEST_F(JoystickWizard, RefusesWhenNoButtonIsPressed) {
  const Stick stick;
  plug_in(stick);
  wizard.event(button_event(2, 1, JS_EVENT_INIT));  // held at open: a state, not a press
  rest();
  sweep(stick.roll, stick.right);
  sweep(stick.pitch, stick.back);
  sweep(stick.yaw, stick.twist_right);
  lift_sweep(stick);
  wizard.event(button_event(2, 1, JS_EVENT_INIT));
  EXPECT_EQ(wizard.step(), WizardStep::fire);
  wizard.next(now);
  ASSERT_EQ(wizard.step(), WizardStep::review);
  ASSERT_EQ(wizard.errors().size(), 1u);
  EXPECT_EQ(wizard.errors()[0], "fire: no button was pressed");
}

TEST_F(JoystickWizard, ControlsShortOfFullDeflectionAreNotedNotRefused) {
  const Stick stick;
  plug_in(stick);
  rest();
  sweep(stick.roll, 20000);
  sweep(stick.pitch, stick.back);
  sweep(stick.yaw, stick.twist_right);
  lift_sweep(stick);
  fire(stick);
  EXPECT_TRUE(wizard.errors().empty());
  ASSERT_EQ(wizard.notes().size(), 1u);
  EXPECT_NE(wizard.notes()[0].find("roll: axis 0 reached only -20000..20000"), std::string::npos) << wizard.notes()[0];
}

TEST_F(JoystickWizard, TheRestStartsAtEnterAndLastsASecond) {
  plug_in(Stick{});
  wizard.tick(now + 5000);
  EXPECT_EQ(wizard.step(), WizardStep::rest) << "waits for Enter";
  EXPECT_FALSE(wizard.resting());
  wizard.next(now);
  EXPECT_TRUE(wizard.resting());
  EXPECT_EQ(wizard.rest_done_permille(now + 500), 500);
  wizard.tick(now + qrterm::JoystickWizard::kRestMs - 1);
  EXPECT_EQ(wizard.step(), WizardStep::rest);
  wizard.next(now + 10);  // Enter again while resting: nothing
  wizard.tick(now + qrterm::JoystickWizard::kRestMs);
  EXPECT_EQ(wizard.step(), WizardStep::roll);
  EXPECT_FALSE(wizard.resting());
}

TEST_F(JoystickWizard, LeadingIsTheAxisMovedMostSoFar) {
  const Stick stick;
  plug_in(stick);
  rest();
  EXPECT_EQ(wizard.leading().max - wizard.leading().min, 0) << "nothing moved yet";
  wizard.event(axis_event(1, 3000));  // pitch wobbles
  wizard.event(axis_event(0, 25000));
  EXPECT_EQ(wizard.leading().axis, 0);
  EXPECT_FALSE(wizard.leading().moved) << "not yet half its range";
  wizard.event(axis_event(0, -25000));
  EXPECT_TRUE(wizard.leading().moved);
  EXPECT_FALSE(wizard.leading().invert);
}

TEST_F(JoystickWizard, RestartForgetsWhatWasFound) {
  const Stick stick;
  run(stick);
  ASSERT_EQ(wizard.step(), WizardStep::review);
  wizard.restart();
  EXPECT_EQ(wizard.step(), WizardStep::rest);
  EXPECT_FALSE(wizard.found(WizardStep::roll).moved);
  EXPECT_FALSE(wizard.fire_button());
  EXPECT_EQ(wizard.axes().size(), 4u) << "where the axes are is kept: a still stick does not report again";
  rest();
  sweep(stick.roll, stick.right);
  sweep(stick.pitch, stick.back);
  wizard.next(now);
  lift_sweep(stick);
  fire(stick);
  EXPECT_TRUE(mentions(wizard.errors(), "yaw: no axis moved")) << "the first run's yaw is not kept";
}

TEST_F(JoystickWizard, TheFileItWritesReadsBackToTheSameMapAndFlies) {
  Stick stick;
  stick.roll = 1;
  stick.pitch = 0;
  stick.lift = 2;
  stick.yaw = 3;
  stick.back = -kFull;
  stick.fire = 2;
  plug_in(stick);
  rest({axis_event(stick.roll, 983)});
  sweep(stick.roll, stick.right, 983);
  sweep(stick.pitch, stick.back);
  sweep(stick.yaw, stick.twist_right);
  lift_sweep(stick);
  fire(stick);
  ASSERT_TRUE(wizard.errors().empty()) << joined(wizard.errors());
  const std::string text = wizard.map_text();
  EXPECT_NE(text.find("#   roll: axis 1, -32767..32767, right reads +\n"), std::string::npos) << text;
  EXPECT_NE(text.find("#   deadband: twice the 30 per mille roll read at rest\n"), std::string::npos) << text;
  const qrterm::JoystickMapFile file = qrterm::parse_joystick_map(text);
  ASSERT_TRUE(file.errors.empty()) << qrterm::describe("text", file.errors);
  const JoystickMap& found = wizard.map();
  for (auto binding : {&JoystickMap::lift, &JoystickMap::roll, &JoystickMap::pitch, &JoystickMap::yaw}) {
    EXPECT_EQ((file.map.*binding).axis, (found.*binding).axis);
    EXPECT_EQ((file.map.*binding).invert, (found.*binding).invert);
  }
  EXPECT_EQ(file.map.abort_button, 2);
  EXPECT_EQ(file.map.deadband_permille, 60);

  // Flown with it: the stick as the pilot moves it gives the pilot's inputs.
  qrterm::JoystickReader reader(file.map);
  for (uint8_t axis = 0; axis < 4; ++axis) reader.feed(axis_event(axis, 0, JS_EVENT_INIT));
  reader.feed(axis_event(stick.lift, kFull, JS_EVENT_INIT));  // closed
  reader.feed(axis_event(stick.roll, 983));                   // resting off centre
  EXPECT_EQ(reader.sticks(), qrterm::Sticks{}) << "at rest: neutral";
  reader.feed(axis_event(stick.roll, kFull));
  reader.feed(axis_event(stick.pitch, -kFull));
  reader.feed(axis_event(stick.lift, -kFull));
  EXPECT_EQ(reader.sticks(), (qrterm::Sticks{1000, 1000, 1000, 0})) << "right, back, open";
  reader.feed(button_event(2, 1));
  EXPECT_TRUE(reader.take_abort());
}

}  // namespace
