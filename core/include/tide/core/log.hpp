#pragma once

#include <functional>
#include <string_view>

namespace tide {

enum class LogLevel { info, warning, error };

/// Receives every message the library logs. The default sink writes warnings and errors to
/// standard error; an embedding program installs its own (or an empty one to silence it).
using LogSink = std::function<void(LogLevel, std::string_view)>;

/// Installs `sink` and returns the one it replaces.
LogSink set_log_sink(LogSink sink);

/// Sends one message to the current sink; safe to call from several threads.
void log_message(LogLevel level, std::string_view message);

inline void log_warning(std::string_view message) { log_message(LogLevel::warning, message); }

}  // namespace tide
