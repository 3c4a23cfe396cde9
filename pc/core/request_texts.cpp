#include <pc/core/request_texts.hpp>

namespace qrterm {
namespace {

struct RequestText {
  wire::MessageType type;
  const char* accepted;  // null: nothing worth a line
  const char* what;
};

constexpr RequestText kRequestTexts[] = {
    {wire::MessageType::mode_change, nullptr, "mode change"},
    {wire::MessageType::param_set, nullptr, "parameter"},
    {wire::MessageType::param_get, nullptr, "parameter read"},  // the reports say it all
    {wire::MessageType::log_start, "QR logging (sensor + telemetry)", "log start"},
    {wire::MessageType::log_stop, "QR logs stopped", "log stop"},
    {wire::MessageType::log_download, nullptr, "log download"},
    {wire::MessageType::log_resend, nullptr, "log part resend"},
    {wire::MessageType::exit, nullptr, "exit"},
    {wire::MessageType::observable_get, nullptr, "observable table request"},
    {wire::MessageType::stream_request, nullptr, "stream request"},
    {wire::MessageType::motor_test, nullptr, "motor test"},
    {wire::MessageType::esc_direction, nullptr, "ESC direction"},  // the QR's debug text says how it ended
};

const RequestText& request_text(wire::MessageType type) {
  for (const RequestText& text : kRequestTexts) {
    if (text.type == type) return text;
  }
  return kRequestTexts[0];
}

}  // namespace

const char* request_what(wire::MessageType type) { return request_text(type).what; }

const char* request_accepted(wire::MessageType type) { return request_text(type).accepted; }

std::string reason_text(wire::NackReason reason) {
  const wire::NackReasonSpec* spec = wire::find_nack_reason(reason);
  return spec != nullptr ? spec->text : "refused";
}

}  // namespace qrterm
