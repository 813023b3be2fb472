#include "gdpn/core/diagnostics.h"

#include <ostream>
#include <sstream>

#include "gdpn/core/text.h"

namespace gdpn::core {

std::string SourceLoc::str() const {
  std::string s = file.empty() ? std::string("<input>") : escapeInvalidUtf8(file);
  if (line > 0) {
    s += ':' + std::to_string(line);
    if (column > 0) s += ':' + std::to_string(column);
  }
  return s;
}

std::string Diagnostic::str() const {
  const char* kind = severity == Severity::Error     ? "error"
                     : severity == Severity::Warning ? "warning"
                                                     : "note";
  return loc.str() + ": " + kind + ": " + message;
}

void Diagnostics::add(Diagnostic d) {
  if (d.severity == Severity::Note) {
    if (!repeating_) list_.push_back(std::move(d));
    return;
  }
  repeating_ = !said_.insert(d.str()).second;
  if (repeating_) return;
  if (d.severity == Severity::Error) ++errors_;
  list_.push_back(std::move(d));
}

void Diagnostics::error(SourceLoc loc, std::string message) { add({Severity::Error, std::move(loc), std::move(message)}); }

void Diagnostics::warning(SourceLoc loc, std::string message) {
  add({Severity::Warning, std::move(loc), std::move(message)});
}

void Diagnostics::note(SourceLoc loc, std::string message) { add({Severity::Note, std::move(loc), std::move(message)}); }

void Diagnostics::print(std::ostream& out) const {
  for (const auto& d : list_) out << d.str() << '\n';
}

std::string Diagnostics::str() const {
  std::ostringstream out;
  print(out);
  return out.str();
}

void Diagnostics::append(const Diagnostics& other) {
  for (const auto& d : other.list_) add(d);
}

}  // namespace gdpn::core
