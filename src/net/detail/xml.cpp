#include "xml.h"

#include <cstdint>

namespace gdpn::net::detail {
namespace {

constexpr int kMaxDepth = 256;

class Parser {
 public:
  Parser(const std::string& text, const std::string& file, core::Diagnostics& diags)
      : s_(text), file_(file), diags_(diags) {}

  std::unique_ptr<XmlElement> document() {
    skipMisc();
    if (failed_) return nullptr;
    if (!peek('<')) return fail("the file holds no XML element");
    auto root = element(0);
    if (!root) return nullptr;
    skipMisc();
    if (!failed_ && i_ < s_.size()) return fail("text after the document's last element");
    return failed_ ? nullptr : std::move(root);
  }

 private:
  core::SourceLoc here() const { return {file_, line_, col_}; }

  std::nullptr_t fail(const std::string& why) {
    if (!failed_) diags_.error(here(), "malformed XML: " + why);
    failed_ = true;
    return nullptr;
  }

  bool peek(char c) const { return i_ < s_.size() && s_[i_] == c; }
  bool starts(const char* lit) const { return s_.compare(i_, std::char_traits<char>::length(lit), lit) == 0; }
  void advance(std::size_t n = 1) {
    for (std::size_t k = 0; k < n && i_ < s_.size(); ++k, ++i_) {
      if (s_[i_] == '\n') {
        ++line_;
        col_ = 1;
      } else {
        ++col_;
      }
    }
  }
  void skipSpace() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r' || s_[i_] == '\n')) advance();
  }
  /// Skips to just past `end`; false (and an error) when it never comes.
  bool skipPast(const char* end, const char* what) {
    const auto at = s_.find(end, i_);
    if (at == std::string::npos) {
      fail(std::string("unterminated ") + what);
      return false;
    }
    advance(at + std::char_traits<char>::length(end) - i_);
    return true;
  }
  /// Comments, processing instructions, DOCTYPE and white space between elements.
  void skipMisc() {
    while (!failed_) {
      skipSpace();
      if (starts("<?")) skipPast("?>", "processing instruction");
      else if (starts("<!--")) skipPast("-->", "comment");
      else if (starts("<!DOCTYPE")) skipPast(">", "DOCTYPE");
      else return;
    }
  }

  static bool nameChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
  }
  std::string name() {
    const auto b = i_;
    while (i_ < s_.size() && nameChar(s_[i_])) advance();
    return s_.substr(b, i_ - b);
  }
  static std::string local(const std::string& n) {
    const auto colon = n.rfind(':');
    return colon == std::string::npos ? n : n.substr(colon + 1);
  }

  /// Decodes entities in raw text.
  std::optional<std::string> decode(const std::string& raw) {
    std::string out;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] != '&') {
        out += raw[k];
        continue;
      }
      const auto semi = raw.find(';', k);
      if (semi == std::string::npos || semi - k > 12) {
        fail("'&' that starts no entity");
        return std::nullopt;
      }
      const std::string ent = raw.substr(k + 1, semi - k - 1);
      if (ent == "lt") out += '<';
      else if (ent == "gt") out += '>';
      else if (ent == "amp") out += '&';
      else if (ent == "quot") out += '"';
      else if (ent == "apos") out += '\'';
      else if (ent.size() > 1 && ent[0] == '#') {
        std::uint32_t cp = 0;
        const bool hex = ent[1] == 'x' || ent[1] == 'X';
        for (std::size_t j = hex ? 2 : 1; j < ent.size(); ++j) {
          const char c = ent[j];
          const int digit = c >= '0' && c <= '9' ? c - '0'
                            : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                            : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                          : -1;
          if (digit < 0 || cp > 0x10ffff) {
            fail("a bad character reference '&" + ent + ";'");
            return std::nullopt;
          }
          cp = cp * (hex ? 16u : 10u) + static_cast<std::uint32_t>(digit);
        }
        if (cp == 0 || cp > 0x10ffff) {
          fail("a bad character reference '&" + ent + ";'");
          return std::nullopt;
        }
        // UTF-8
        if (cp < 0x80) out += static_cast<char>(cp);
        else if (cp < 0x800) out += {static_cast<char>(0xc0 | (cp >> 6)), static_cast<char>(0x80 | (cp & 0x3f))};
        else if (cp < 0x10000) out += {static_cast<char>(0xe0 | (cp >> 12)), static_cast<char>(0x80 | ((cp >> 6) & 0x3f)),
                                       static_cast<char>(0x80 | (cp & 0x3f))};
        else out += {static_cast<char>(0xf0 | (cp >> 18)), static_cast<char>(0x80 | ((cp >> 12) & 0x3f)),
                     static_cast<char>(0x80 | ((cp >> 6) & 0x3f)), static_cast<char>(0x80 | (cp & 0x3f))};
      } else {
        fail("an unknown entity '&" + ent + ";'");
        return std::nullopt;
      }
      k = semi;
    }
    return out;
  }

  std::unique_ptr<XmlElement> element(int depth) {
    if (depth > kMaxDepth) return fail("elements nested deeper than " + std::to_string(kMaxDepth));
    auto el = std::make_unique<XmlElement>();
    el->loc = here();
    advance();  // '<'
    const std::string qname = name();
    if (qname.empty()) return fail("an element without a name");
    el->name = local(qname);
    // attributes
    while (true) {
      skipSpace();
      if (i_ >= s_.size()) return fail("the document ends inside <" + qname + ">");
      if (starts("/>")) {
        advance(2);
        return el;
      }
      if (peek('>')) {
        advance();
        break;
      }
      const std::string key = name();
      if (key.empty()) return fail("an unexpected '" + std::string(1, s_[i_]) + "' in <" + qname + ">");
      skipSpace();
      if (!peek('=')) return fail("attribute '" + key + "' has no value");
      advance();
      skipSpace();
      if (!peek('"') && !peek('\'')) return fail("attribute '" + key + "' needs a quoted value");
      const char quote = s_[i_];
      advance();
      const auto end = s_.find(quote, i_);
      if (end == std::string::npos) return fail("an unterminated attribute value");
      const std::string raw = s_.substr(i_, end - i_);
      advance(end + 1 - i_);
      auto value = decode(raw);
      if (!value) return nullptr;
      el->attrs.emplace_back(local(key), std::move(*value));
    }
    // content
    while (true) {
      if (i_ >= s_.size()) return fail("<" + qname + "> is never closed");
      if (starts("</")) {
        const core::SourceLoc at = here();
        advance(2);
        const std::string end = name();
        if (end != qname) {
          line_ = at.line, col_ = at.column;  // report it where the end tag starts
          return fail("</" + end + "> closes <" + qname + ">");
        }
        skipSpace();
        if (!peek('>')) return fail("an unfinished end tag </" + end);
        advance();
        return el;
      }
      if (starts("<!--")) {
        if (!skipPast("-->", "comment")) return nullptr;
      } else if (starts("<![CDATA[")) {
        advance(9);
        const auto end = s_.find("]]>", i_);
        if (end == std::string::npos) return fail("an unterminated CDATA section");
        el->text += s_.substr(i_, end - i_);
        advance(end + 3 - i_);
      } else if (starts("<?")) {
        if (!skipPast("?>", "processing instruction")) return nullptr;
      } else if (peek('<')) {
        auto child = element(depth + 1);
        if (!child) return nullptr;
        el->children.push_back(std::move(child));
      } else {
        const auto end = s_.find('<', i_);
        const std::string raw = s_.substr(i_, end == std::string::npos ? std::string::npos : end - i_);
        advance(raw.size());
        auto text = decode(raw);
        if (!text) return nullptr;
        el->text += *text;
      }
    }
  }

  const std::string& s_;
  std::string file_;
  core::Diagnostics& diags_;
  std::size_t i_ = 0;
  int line_ = 1, col_ = 1;
  bool failed_ = false;
};

}  // namespace

const std::string* XmlElement::attr(const std::string& key) const {
  for (const auto& [k, v] : attrs) {
    if (k == key) return &v;
  }
  return nullptr;
}

const XmlElement* XmlElement::child(const std::string& n) const {
  for (const auto& c : children) {
    if (c->name == n) return c.get();
  }
  return nullptr;
}

std::unique_ptr<XmlElement> parseXml(const std::string& text, const std::string& file, core::Diagnostics& diags) {
  return Parser(text, file, diags).document();
}

}  // namespace gdpn::net::detail
