// All typed messages, and dispatch: from a received frame to a call with the decoded message.
#pragma once

#include <stdint.h>

#include <common/frame.hpp>
#include <common/log_records.hpp>
#include <common/observable_messages.hpp>
#include <common/payload_codec.hpp>
#include <common/replies.hpp>
#include <common/requests.hpp>
#include <common/telemetry.hpp>

namespace wire {

template <class... Msgs>
struct MessageList {
  static constexpr size_t size = sizeof...(Msgs);
};

// One struct per row of kMessageTable. The static checks below keep the two in step.
using AllMessages =
    MessageList<Control, ModeChange, ParamSet, ParamGet, LogStart, LogStop, LogDownload, Exit, Ack, Nack, ParamReport,
                DebugText, TelemetryAttitude, TelemetryRates, TelemetryEngines, TelemetrySetpoints, TelemetrySystem,
                TelemetryLink, SensorLogPart, TelemetryLogPart, TelemetryTask, LogStatus, TelemetryHeight,
                TelemetryRadio, TelemetryRpm, ObservableGet, StreamRequest, ObservableInfo, ObservableText,
                ObservableSamples, LogResend, MotorTest, EscDirection>;

// What the QR receives: it never decodes a message of the other direction (its parser drops them).
using PcToQrMessages = MessageList<Control, ModeChange, ParamSet, ParamGet, LogStart, LogStop, LogDownload, Exit,
                                   ObservableGet, StreamRequest, LogResend, MotorTest, EscDirection>;

template <class... Msgs>
constexpr bool covers_table(MessageList<Msgs...>) {
  for (const MessageSpec& spec : kMessageTable) {
    if (((Msgs::kType == spec.type ? 1 : 0) + ... + 0) != 1) return false;
  }
  return sizeof...(Msgs) == kMessageCount && (Message<Msgs> && ...);
}
static_assert(covers_table(AllMessages{}), "every table row has exactly one message struct, of the table's length");

template <class... Msgs>
constexpr bool all_of_direction(MessageList<Msgs...>, Direction direction) {
  size_t rows = 0;
  for (const MessageSpec& spec : kMessageTable) rows += spec.direction == direction ? 1 : 0;
  return rows == sizeof...(Msgs) && ((message_spec(Msgs::kType)->direction == direction) && ...);
}
static_assert(all_of_direction(PcToQrMessages{}, Direction::pc_to_qr), "PcToQrMessages: every PC -> QR message");

enum class DispatchResult : uint8_t {
  handled,          // decoded and passed to the handler
  invalid_payload,  // right length and check, but a field out of range: answer requests with bad_value
  not_handled,      // decoded, but the handler has no overload for this message
};

namespace detail {

template <class Msg, class Handler>
bool dispatch_one(const Frame& frame, Handler& handler, DispatchResult& result) {
  if (frame.type != Msg::kType) return false;
  Msg message;
  if (!decode(frame, message)) {
    result = DispatchResult::invalid_payload;
  } else if constexpr (requires { handler(message); }) {
    handler(message);
    result = DispatchResult::handled;
  } else {
    result = DispatchResult::not_handled;
  }
  return true;
}

template <class Handler, class... Msgs>
DispatchResult dispatch(const Frame& frame, Handler& handler, MessageList<Msgs...>) {
  DispatchResult result = DispatchResult::not_handled;
  (dispatch_one<Msgs>(frame, handler, result) || ...);
  return result;
}

}  // namespace detail

// Decodes `frame` as the message its type names and calls the handler's overload for it, e.g.
//   struct Pc { void operator()(const TelemetryAttitude&); void operator()(const Ack&); ... };
// A handler need not handle every message.
template <class Handler>
DispatchResult dispatch(const Frame& frame, Handler&& handler) {
  return detail::dispatch(frame, handler, AllMessages{});
}

// The same over a subset of the messages (the QR: PcToQrMessages).
template <class List, class Handler>
DispatchResult dispatch(const Frame& frame, Handler&& handler) {
  return detail::dispatch(frame, handler, List{});
}

}  // namespace wire
