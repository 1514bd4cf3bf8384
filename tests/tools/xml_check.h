#pragma once
// A tiny XML well-formedness checker for the export tests: one root element, balanced and
// matching tags, quoted attributes without '<', no duplicate attributes, text and attribute
// values whose '&' starts a known entity or a character reference, comments, processing
// instructions. Not a validating parser; enough to catch broken escaping and unbalanced
// output. Returns an empty string when well-formed, else what is wrong and where.

#include <cctype>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace ossa::test {

inline std::string xml_error(std::string_view xml) {
  auto at = [&](size_t i, const std::string& what) {
    return what + " at offset " + std::to_string(i);
  };
  auto name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
           c == ':';
  };
  auto check_text = [&](size_t from, size_t to) -> std::string {
    for (size_t i = from; i < to; ++i) {
      if (xml[i] == '<') return at(i, "raw '<' in text");
      if (xml[i] == '&') {
        const size_t semi = xml.find(';', i);
        if (semi == std::string_view::npos || semi > to) return at(i, "unterminated entity");
        const std::string_view ent = xml.substr(i + 1, semi - i - 1);
        const bool named = ent == "amp" || ent == "lt" || ent == "gt" || ent == "quot" ||
                           ent == "apos";
        const bool numeric = ent.size() > 1 && ent[0] == '#';
        if (!named && !numeric) return at(i, "unknown entity &" + std::string(ent) + ";");
      }
    }
    return {};
  };
  std::vector<std::string> stack;
  bool root_seen = false;
  size_t i = 0;
  const size_t n = xml.size();
  while (i < n) {
    const size_t lt = xml.find('<', i);
    const size_t text_end = lt == std::string_view::npos ? n : lt;
    std::string err = check_text(i, text_end);
    if (!err.empty()) return err;
    if (stack.empty()) {
      for (size_t k = i; k < text_end; ++k) {
        if (!std::isspace(static_cast<unsigned char>(xml[k]))) return at(k, "text outside the root");
      }
    }
    if (lt == std::string_view::npos) break;
    i = lt;
    if (xml.substr(i, 4) == "<!--") {
      const size_t end = xml.find("-->", i + 4);
      if (end == std::string_view::npos) return at(i, "unterminated comment");
      i = end + 3;
      continue;
    }
    if (xml.substr(i, 2) == "<?") {
      const size_t end = xml.find("?>", i + 2);
      if (end == std::string_view::npos) return at(i, "unterminated processing instruction");
      i = end + 2;
      continue;
    }
    const bool closing = xml.substr(i, 2) == "</";
    size_t k = i + (closing ? 2 : 1);
    const size_t name_start = k;
    while (k < n && name_char(xml[k])) ++k;
    if (k == name_start) return at(i, "tag without a name");
    const std::string name(xml.substr(name_start, k - name_start));
    if (closing) {
      while (k < n && std::isspace(static_cast<unsigned char>(xml[k]))) ++k;
      if (k >= n || xml[k] != '>') return at(k, "malformed end tag </" + name);
      if (stack.empty() || stack.back() != name) {
        return at(i, "end tag </" + name + "> does not match <" +
                         (stack.empty() ? std::string("(none)") : stack.back()) + ">");
      }
      stack.pop_back();
      i = k + 1;
      continue;
    }
    if (stack.empty() && root_seen) return at(i, "second root element <" + name + ">");
    root_seen = true;
    std::set<std::string> attrs;
    bool self_closing = false;
    while (true) {
      const size_t ws = k;
      while (k < n && std::isspace(static_cast<unsigned char>(xml[k]))) ++k;
      if (k >= n) return at(i, "unterminated tag <" + name);
      if (xml[k] == '>') { ++k; break; }
      if (xml.substr(k, 2) == "/>") { k += 2; self_closing = true; break; }
      if (k == ws) return at(k, "missing space before attribute in <" + name);
      const size_t a0 = k;
      while (k < n && name_char(xml[k])) ++k;
      if (k == a0) return at(k, "bad attribute name in <" + name);
      const std::string attr(xml.substr(a0, k - a0));
      if (!attrs.insert(attr).second) return at(a0, "duplicate attribute " + attr);
      if (k >= n || xml[k] != '=') return at(k, "attribute " + attr + " without '='");
      ++k;
      if (k >= n || (xml[k] != '"' && xml[k] != '\'')) return at(k, "unquoted attribute " + attr);
      const char q = xml[k];
      const size_t v0 = ++k;
      const size_t v1 = xml.find(q, v0);
      if (v1 == std::string_view::npos) return at(v0, "unterminated attribute " + attr);
      err = check_text(v0, v1);
      if (!err.empty()) return err;
      k = v1 + 1;
    }
    if (!self_closing) stack.push_back(name);
    i = k;
  }
  if (!root_seen) return "no root element";
  if (!stack.empty()) return "unclosed element <" + stack.back() + ">";
  return {};
}

}  // namespace ossa::test
