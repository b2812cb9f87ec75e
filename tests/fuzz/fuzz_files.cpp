#include "fuzz/fuzz_files.hpp"

#include <unistd.h>
#include <fstream>
#include <string_view>

namespace yardsim::fuzz {

namespace {
constexpr std::string_view kMarker = "#@ file ";

// (text after the marker) => a safe file name, or "" when it is not one
std::string safeName(std::string_view s) {
  if (s.empty() || s.size() > 64 || s == "." || s.find("..") != std::string_view::npos) return "";
  for (const char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return "";
  return std::string(s);
}
}  // namespace

std::vector<std::pair<std::string, std::string>> splitFiles(const std::uint8_t* data,
                                                            std::size_t size,
                                                            const std::string& firstName) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, std::string>> files{{firstName, ""}};
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    const std::string name =
        line.substr(0, kMarker.size()) == kMarker ? safeName(line.substr(kMarker.size())) : "";
    if (!name.empty()) {
      if (files.size() == 1 && files[0].second.empty())
        files[0].first = name;  // the marker opens the first file
      else
        files.emplace_back(name, "");
    } else {
      files.back().second.append(line);
      if (end < text.size()) files.back().second.push_back('\n');
    }
    pos = end + 1;
  }
  return files;
}

std::filesystem::path writeFiles(const std::vector<std::pair<std::string, std::string>>& files) {
  static const std::filesystem::path dir = [] {
    const auto d =
        std::filesystem::temp_directory_path() / ("yardsim_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    std::filesystem::remove_all(entry.path());
  for (const auto& [name, content] : files) std::ofstream(dir / name, std::ios::binary) << content;
  return dir;
}

}  // namespace yardsim::fuzz
