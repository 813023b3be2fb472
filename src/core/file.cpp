#include "gdpn/core/file.h"

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
  const auto bad = firstInvalidUtf8(text);
  if (bad == std::string::npos) return true;
  const auto [line, column] = lineColumn(text, bad);
  diags.error({file, line, column}, "the file is not valid UTF-8 text here");
  return false;
}

}  // namespace gdpn::core
