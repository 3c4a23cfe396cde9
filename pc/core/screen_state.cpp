#include <pc/core/screen_state.hpp>

#include <vector>

#include <pc/core/completion.hpp>

namespace qrterm {

ScreenState::Taken ScreenState::key(Key key, double now_s) {
  if (prompt_ && key != kKeyEscape && key != kKeyInterrupt) {
    prompt_key(key);
    return Taken::by_prompt;
  }
  prompt_.reset();
  if (key == kKeyTab) {
    help_ = false;
    const Screen left = screen_;
    // The orientation check is off the round: Tab leaves it for the cockpit.
    const size_t next = static_cast<size_t>(screen_) + 1;
    screen_ = static_cast<Screen>(next >= kTabScreens ? 0 : next);
    // The radio screen has the QR's streams while it is shown (docs/protocol.md section 13.5).
    if (screen_ == Screen::radio) streams_.open_radio();
    if (left == Screen::radio) streams_.close_radio();
    return Taken::by_screen;
  }
  if (screen_key(key, now_s)) {
    help_ = false;
    return Taken::by_screen;
  }
  return Taken::no;
}

bool ScreenState::screen_key(Key key, double now_s) {
  PlotModel& plot = streams_.plot();
  switch (screen_action(screen_, key)) {
    case ScreenAction::none: return false;
    case ScreenAction::plot_pick: prompt_ = Prompt{PromptKind::observables, ""}; break;
    case ScreenAction::plot_remove_last: streams_.remove_last(); break;
    case ScreenAction::plot_window: plot.next_window(); break;
    case ScreenAction::plot_scale: plot.toggle_scale(now_s); break;
    case ScreenAction::plot_zoom_in: plot.zoom(0.5, now_s); break;
    case ScreenAction::plot_zoom_out: plot.zoom(2.0, now_s); break;
    case ScreenAction::plot_freeze: plot.toggle_freeze(now_s); break;
    case ScreenAction::plot_faster: streams_.faster(); break;
    case ScreenAction::plot_slower: streams_.slower(); break;
    case ScreenAction::param_previous: editor_.move(-1); break;
    case ScreenAction::param_next: editor_.move(1); break;
    case ScreenAction::param_step_down: editor_.step(parameters_, -1); break;
    case ScreenAction::param_step_up: editor_.step(parameters_, 1); break;
    case ScreenAction::param_type: prompt_ = Prompt{PromptKind::value, ""}; break;
    case ScreenAction::param_default: editor_.reset_default(parameters_); break;
    case ScreenAction::param_all_defaults: {
      const size_t changed = editor_.reset_all_defaults(parameters_);
      note_(Severity::info, changed == 0 ? std::string("every parameter is at its default already")
                                         : "every parameter to its default: " + std::to_string(changed) + " changed");
      break;
    }
    case ScreenAction::param_save: prompt_ = Prompt{PromptKind::save, editor_.file_name()}; break;
    case ScreenAction::param_load: prompt_ = Prompt{PromptKind::load, ""}; break;
    case ScreenAction::param_take_tuned: autotune_.accept(parameters_); break;
    case ScreenAction::param_back_from_tuned: autotune_.back(parameters_); break;
    case ScreenAction::radio_ends_again: streams_.radio().restart_ends(); break;
    case ScreenAction::orientation_enter: check_.enter(); break;
    case ScreenAction::orientation_restart: check_.start(); break;
  }
  return true;
}

void ScreenState::prompt_key(Key key) {
  Prompt& prompt = *prompt_;
  if (key == kKeyEnter) {
    const Prompt done = prompt;
    prompt_.reset();
    return submit(done);
  }
  if (key == kKeyBackspace) {
    if (!prompt.text.empty()) prompt.text.pop_back();
    return;
  }
  if (key == kKeyTab && prompt.kind == PromptKind::observables) {
    // As a shell: the one name that fits, or the start the candidates share (the screen lists them).
    prompt.text = complete_last_word(prompt.text, streams_.catalog().names_starting(last_word(prompt.text))).text;
    return;
  }
  if (key >= ' ' && key < 0x7F && prompt.text.size() < 64) prompt.text += static_cast<char>(key);
}

void ScreenState::submit(const Prompt& prompt) {
  switch (prompt.kind) {
    case PromptKind::observables: streams_.pick(prompt.text); break;
    case PromptKind::value: {
      const std::string error = editor_.set_typed(parameters_, prompt.text);
      if (!error.empty()) note_(Severity::warning, error);
      break;
    }
    case PromptKind::save: {
      const std::string error = editor_.save(parameters_, prompt.text);
      note_(error.empty() ? Severity::info : Severity::error,
            error.empty() ? "parameters saved to " + prompt.text : error);
      break;
    }
    case PromptKind::load: {
      const std::string error = editor_.load(parameters_, prompt.text);
      note_(error.empty() ? Severity::info : Severity::error,
            error.empty() ? "parameters loaded from " + prompt.text : error);
      break;
    }
  }
}

}  // namespace qrterm
