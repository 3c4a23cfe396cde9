// The plot, parameter, radio, orientation check and motor test screens, drawn below the status rows every
// screen shares (title, mode and link, battery and CPU, QR flags). Each ends in the pilot's prompt
// or the newest log line.
#pragma once

#include <pc/core/console.hpp>

namespace qrterm {

// `braille`: the terminal takes UTF-8 (terminal_speaks_utf8()).
void draw_plot_screen(const Console& console, int top, int rows, int width, bool braille);
void draw_parameter_screen(const Console& console, int top, int rows, int width);
// The motor test's rows from `top`; returns the first row below them.
int draw_motor_test_screen(const Console& console, int top, int width);
void draw_radio_screen(const Console& console, int top, int rows, int width);
void draw_orientation_screen(const Console& console, int top, int rows, int width);
// The prompt being typed, else the newest log line, on `row`.
void draw_prompt_or_log(const Console& console, int row, int width);

}  // namespace qrterm
