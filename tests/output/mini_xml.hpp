// Just enough XML to check the XDMF we write (elements, attributes, text; no entities beyond the
// five predefined, no CDATA), so the tests need no XML library. Throws std::runtime_error on
// anything malformed, which is what the tests want to catch.
#pragma once

#include <cctype>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mini_xml {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  // concatenated, trimmed
  std::vector<Element> children;

  std::vector<const Element*> all(const std::string& child_name) const {
    std::vector<const Element*> out;
    for (const auto& c : children)
      if (c.name == child_name) out.push_back(&c);
    return out;
  }
  const Element& one(const std::string& child_name) const {
    auto found = all(child_name);
    if (found.size() != 1)
      throw std::runtime_error("<" + name + "> has " + std::to_string(found.size()) + " <" +
                               child_name + ">, expected 1");
    return *found.front();
  }
  std::string attr(const std::string& key) const {
    auto it = attributes.find(key);
    if (it == attributes.end()) throw std::runtime_error("<" + name + "> lacks " + key);
    return it->second;
  }
};

namespace detail {

inline std::string unescape(const std::string& s) {
  static const std::pair<const char*, char> table[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool replaced = false;
    if (s[i] == '&') {
      for (const auto& [from, to] : table) {
        const std::string f = from;
        if (s.compare(i, f.size(), f) == 0) {
          out += to;
          i += f.size();
          replaced = true;
          break;
        }
      }
      if (!replaced) throw std::runtime_error("unknown entity in '" + s + "'");
    } else {
      out += s[i++];
    }
  }
  return out;
}

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

class Parser {
 public:
  explicit Parser(const std::string& s) : s_(s) {}

  Element document() {
    skip_misc();
    Element root = element();
    skip_misc();
    if (i_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("XML: " + what + " at offset " + std::to_string(i_));
  }
  bool starts(const char* p) const { return s_.compare(i_, std::string(p).size(), p) == 0; }
  void skip_space() {
    while (i_ < s_.size() && std::string(" \t\r\n").find(s_[i_]) != std::string::npos) ++i_;
  }
  void skip_until(const char* end) {
    const auto e = s_.find(end, i_);
    if (e == std::string::npos) fail(std::string("missing ") + end);
    i_ = e + std::string(end).size();
  }
  // Prolog, doctype, comments.
  void skip_misc() {
    for (;;) {
      skip_space();
      if (starts("<?"))
        skip_until("?>");
      else if (starts("<!--"))
        skip_until("-->");
      else if (starts("<!"))
        skip_until(">");
      else
        return;
    }
  }
  std::string name() {
    const auto b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' ||
                              s_[i_] == '-' || s_[i_] == ':' || s_[i_] == '.'))
      ++i_;
    if (b == i_) fail("expected a name");
    return s_.substr(b, i_ - b);
  }
  Element element() {
    if (!starts("<")) fail("expected '<'");
    ++i_;
    Element e;
    e.name = name();
    for (;;) {
      skip_space();
      if (starts("/>")) {
        i_ += 2;
        return e;
      }
      if (starts(">")) {
        ++i_;
        break;
      }
      const std::string key = name();
      skip_space();
      if (!starts("=")) fail("expected '='");
      ++i_;
      skip_space();
      if (!starts("\"")) fail("expected '\"'");
      const auto end = s_.find('"', ++i_);
      if (end == std::string::npos) fail("unterminated attribute");
      if (!e.attributes.emplace(key, unescape(s_.substr(i_, end - i_))).second)
        fail("duplicate attribute " + key);
      i_ = end + 1;
    }
    std::string text;
    for (;;) {
      if (i_ >= s_.size()) fail("unterminated <" + e.name + ">");
      if (starts("<!--")) {
        skip_until("-->");
      } else if (starts("</")) {
        i_ += 2;
        if (name() != e.name) fail("mismatched end tag for <" + e.name + ">");
        skip_space();
        if (!starts(">")) fail("expected '>'");
        ++i_;
        e.text = trim(unescape(text));
        return e;
      } else if (starts("<")) {
        e.children.push_back(element());
      } else {
        text += s_[i_++];
      }
    }
  }

  const std::string& s_;
  std::size_t i_ = 0;
};

}  // namespace detail

inline Element parse(const std::string& text) { return detail::Parser(text).document(); }

}  // namespace mini_xml
