#include "tide/core/log.hpp"

#include <iostream>
#include <mutex>
#include <utility>

namespace tide {
namespace {

void standard_error_sink(LogLevel level, std::string_view message) {
  if (level == LogLevel::info) return;
  std::cerr << "tide: " << (level == LogLevel::warning ? "warning: " : "error: ") << message << '\n';
}

std::mutex& sink_mutex() {
  static std::mutex mutex;
  return mutex;
}

LogSink& current_sink() {
  static LogSink sink = standard_error_sink;
  return sink;
}

}  // namespace

LogSink set_log_sink(LogSink sink) {
  const std::lock_guard lock(sink_mutex());
  return std::exchange(current_sink(), std::move(sink));
}

void log_message(LogLevel level, std::string_view message) {
  const std::lock_guard lock(sink_mutex());
  if (current_sink()) current_sink()(level, message);
}

}  // namespace tide
