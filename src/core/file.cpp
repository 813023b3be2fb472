#include "gdpn/core/file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/core/text.h"

namespace gdpn::core {

std::optional<std::string> readFile(const std::string& path, Diagnostics& diags) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    diags.error({path, 0, 0}, "is a folder, not a file");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.error({path, 0, 0}, "cannot read the file");
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    diags.error({path, 0, 0}, "cannot read the file");
    return std::nullopt;
  }
  return text.str();
}

bool checkUtf8(const std::string& text, const std::string& file, Diagnostics& diags) {
  // YAML and XML both allow no C0 control character but tab, line feed and carriage return
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
      const auto [line, column] = lineColumn(text, i);
      char code[8];
      std::snprintf(code, sizeof code, "%04X", c);
      diags.error({file, line, column}, std::string("control character U+") + code + " is not allowed in the file");
      return false;
    }
  }
  const auto bad = firstInvalidUtf8(text);
  if (bad == std::string::npos) return true;
  const auto [line, column] = lineColumn(text, bad);
  diags.error({file, line, column}, "the file is not valid UTF-8 text here");
  return false;
}

}  // namespace gdpn::core
