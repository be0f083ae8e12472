#pragma once

// A small strict XML reader: enough for XDMF and VTK's XML headers (elements, attributes, text,
// comments, the prolog), and a malformed document is an error rather than something to skip over.

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tide::testing_support {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<XmlElement> children;

  std::vector<const XmlElement*> all(std::string_view child_name) const {
    std::vector<const XmlElement*> found;
    for (const XmlElement& child : children)
      if (child.name == child_name) found.push_back(&child);
    return found;
  }
  const XmlElement& only(std::string_view child_name) const {
    const auto found = all(child_name);
    if (found.size() != 1)
      throw std::runtime_error("<" + name + "> has " + std::to_string(found.size()) + " <" + std::string(child_name) +
                               "> children, expected one");
    return *found.front();
  }
  const std::string& attribute(const std::string& key) const {
    const auto it = attributes.find(key);
    if (it == attributes.end()) throw std::runtime_error("<" + name + "> has no attribute " + key);
    return it->second;
  }
};

class XmlParser {
 public:
  explicit XmlParser(std::string_view text) : text_(text) {}

  XmlElement parse_document() {
    skip_prolog_and_comments();
    XmlElement root = parse_element();
    skip_prolog_and_comments();
    if (position_ != text_.size()) fail("content after the root element");
    return root;
  }

 private:
  bool at(std::string_view token) const { return text_.substr(position_).starts_with(token); }

  void skip_space() {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_]))) ++position_;
  }

  void skip_past(std::string_view terminator) {
    const std::size_t end = text_.find(terminator, position_);
    if (end == std::string_view::npos) fail("missing " + std::string(terminator));
    position_ = end + terminator.size();
  }

  void expect(char c) {
    if (position_ >= text_.size() || text_[position_] != c) fail(std::string("expected '") + c + "'");
    ++position_;
  }

  void skip_prolog_and_comments() {
    for (skip_space(); at("<?") || at("<!"); skip_space()) skip_past(at("<?") ? "?>" : at("<!--") ? "-->" : ">");
  }

  std::string parse_name() {
    const std::size_t start = position_;
    while (position_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[position_])) ||
                                        std::string_view("_:-.").find(text_[position_]) != std::string_view::npos))
      ++position_;
    if (position_ == start) fail("expected a name");
    return std::string(text_.substr(start, position_ - start));
  }

  std::string unescape(std::string_view raw) {
    static const std::map<std::string_view, char> entities = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string text;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        text += raw[i];
        continue;
      }
      const std::size_t end = raw.find(';', i);
      const auto entity = end == std::string_view::npos ? entities.end() : entities.find(raw.substr(i, end - i + 1));
      if (entity == entities.end()) fail("unknown entity");
      text += entity->second;
      i = end;
    }
    return text;
  }

  XmlElement parse_element() {
    expect('<');
    XmlElement element;
    element.name = parse_name();
    for (;;) {
      skip_space();
      if (at("/>")) {
        position_ += 2;
        return element;
      }
      if (at(">")) {
        ++position_;
        break;
      }
      const std::string key = parse_name();
      skip_space();
      expect('=');
      skip_space();
      const char quote = position_ < text_.size() ? text_[position_] : '\0';
      if (quote != '"' && quote != '\'') fail("unquoted attribute value");
      const std::size_t end = text_.find(quote, ++position_);
      if (end == std::string_view::npos) fail("unterminated attribute value");
      if (!element.attributes.emplace(key, unescape(text_.substr(position_, end - position_))).second)
        fail("attribute " + key + " given twice");
      position_ = end + 1;
    }
    for (;;) {
      const std::size_t tag = text_.find('<', position_);
      if (tag == std::string_view::npos) fail("<" + element.name + "> is never closed");
      element.text += unescape(text_.substr(position_, tag - position_));
      position_ = tag;
      if (at("<!--")) {
        skip_past("-->");
      } else if (at("</")) {
        position_ += 2;
        if (parse_name() != element.name) fail("</...> does not match <" + element.name + ">");
        skip_space();
        expect('>');
        break;
      } else {
        element.children.push_back(parse_element());
      }
    }
    const auto first = element.text.find_first_not_of(" \t\r\n");
    element.text = first == std::string::npos
                       ? std::string()
                       : element.text.substr(first, element.text.find_last_not_of(" \t\r\n") - first + 1);
    return element;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("not well-formed XML at offset " + std::to_string(position_) + ": " + what);
  }

  std::string_view text_;
  std::size_t position_ = 0;
};

inline XmlElement parse_xml_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return XmlParser(text.str()).parse_document();
}

}  // namespace tide::testing_support
