#pragma once
// Internal: no promises. A small, strict XML reader for PNML: elements, attributes, text,
// with the line and column of each element; comments, processing instructions, DOCTYPE and
// CDATA handled; the five named entities and numeric references decoded.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"

namespace gdpn::net::detail {

struct XmlElement {
  std::string name;                                        // local name (a prefix is dropped)
  std::vector<std::pair<std::string, std::string>> attrs;  // in document order
  std::vector<std::unique_ptr<XmlElement>> children;
  std::string text;                                        // the text directly inside
  core::SourceLoc loc;                                     // where its '<' is

  /// The attribute `key`, or null.
  [[nodiscard]] const std::string* attr(const std::string& key) const;
  /// The first child called `name`, or null.
  [[nodiscard]] const XmlElement* child(const std::string& name) const;
};

/// Parses `text`; a malformed document gives a located diagnostic and nullopt.
std::unique_ptr<XmlElement> parseXml(const std::string& text, const std::string& file, core::Diagnostics& diags);

}  // namespace gdpn::net::detail
