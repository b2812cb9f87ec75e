#include "output/html_page.hpp"

#include <fstream>
#include <stdexcept>

#include "output/report_bundle.hpp"

namespace yardsim::output {
namespace {

// (text) => safe inside <script>: no "</" that could close the element
std::string scriptSafe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

}  // namespace

std::string htmlPage(const std::string& title, std::string dataJson) {
  std::string html = "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                     "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>";
  for (char c : title) html += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
  html += "</title>\n</head>\n<body>\n<script type=\"application/json\" id=\"yardsim-data\">" +
          scriptSafe(std::move(dataJson)) + "</script>\n<script>" +
          scriptSafe(std::string(reportBundle())) + "</script>\n</body>\n</html>\n";
  return html;
}

void writeTextFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace yardsim::output
