#include "scene_json.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>
#include <vector>

#include "tide/core/scene_error.hpp"

namespace tide::io {

using nlohmann::json;
using scene::SceneError;

std::string pointer_token(std::string_view key) {
  std::string token;
  for (const char c : key) {
    if (c == '~') {
      token += "~0";
    } else if (c == '/') {
      token += "~1";
    } else {
      token += c;
    }
  }
  return token;
}

std::string describe(const json& value) {
  constexpr std::size_t longest = 60;
  std::string text = value.dump();
  if (text.size() > longest) text = text.substr(0, longest) + "...";
  return text;
}

Node child(const Node& object, std::string_view key) {
  const auto member = object.value->find(std::string(key));
  return {member == object.value->end() ? nullptr : &*member, object.path + "/" + pointer_token(key)};
}

Node element(const Node& array, std::size_t index) {
  return {&(*array.value)[index], array.path + "/" + std::to_string(index)};
}

namespace {

/// nlohmann::json keeps only the last of two equal keys in an object, without a word. In a scene
/// that is an editing mistake (two "solver" blocks, one of them ignored), so the parser's
/// callback refuses it. It follows the path of the value being read, for the message.
/// It also refuses nesting deeper than max_nesting: a scene needs 6 levels, and describing a
/// value nested thousands deep in a message (json::dump recurses) would overflow the stack.
class DuplicateKeyGuard {
 public:
  static constexpr std::size_t max_nesting = 64;

  explicit DuplicateKeyGuard(const std::string& file) : file_(file) {}

  void on_event(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (open_.size() == max_nesting) {
          throw SceneError(file_, current_path(),
                           "at most " + std::to_string(max_nesting) + " levels of nested arrays and objects",
                           "deeper nesting");
        }
        open_.emplace_back();
        open_.back().is_array = event == json::parse_event_t::array_start;
        break;
      case json::parse_event_t::key:
        on_key(parsed.get<std::string>());
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open_.pop_back();
        finish_value();
        break;
      case json::parse_event_t::value:
        finish_value();
        break;
    }
  }

 private:
  /// An object or array whose end the parser has not reached yet.
  struct OpenContainer {
    bool is_array = false;
    std::size_t index = 0;  // of the element being read, in an array
    std::string key;        // of the member being read, in an object
    std::set<std::string> keys;
  };

  void on_key(std::string key) {
    OpenContainer& object = open_.back();
    object.key = std::move(key);
    if (!object.keys.insert(object.key).second) {
      throw SceneError(file_, current_path(), "each key at most once in an object",
                       "\"" + object.key + "\" a second time");
    }
  }

  void finish_value() {
    if (!open_.empty() && open_.back().is_array) ++open_.back().index;
  }

  std::string current_path() const {
    std::string path;
    for (const OpenContainer& container : open_) {
      path += "/" + (container.is_array ? std::to_string(container.index) : pointer_token(container.key));
    }
    return path;
  }

  const std::string& file_;
  std::vector<OpenContainer> open_;
};

/// nlohmann's message without its "[json.exception.parse_error.101] parse error at line L,
/// column C: " prefix, which the SceneError's own location replaces.
std::string error_detail(const json::exception& error) {
  const std::string message = error.what();
  const std::size_t id_end = message.find("] ");
  const std::size_t start = id_end == std::string::npos ? 0 : id_end + 2;
  const std::size_t column = message.find("column ", start);
  const std::size_t detail = column == std::string::npos ? column : message.find(": ", column);
  return detail == std::string::npos ? message.substr(start) : message.substr(detail + 2);
}

}  // namespace

json parse_json(std::string_view text, const std::string& file) {
  DuplicateKeyGuard guard(file);
  const json::parser_callback_t callback = [&guard](int, json::parse_event_t event, json& parsed) {
    guard.on_event(event, parsed);
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), callback, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& error) {
    // error.byte counts the characters read, the offending one included.
    const std::string_view before = text.substr(0, error.byte > 0 ? std::min(error.byte - 1, text.size()) : 0);
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
    throw SceneError::syntax(file, line, before.size() - line_start + 1, error_detail(error));
  } catch (const json::out_of_range& error) {
    // A number too large for a double is refused by the parser with no position.
    throw SceneError(file, "", "valid JSON", error_detail(error));
  }
}

}  // namespace tide::io
