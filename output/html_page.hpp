#pragma once
// The frame of every page the report bundle draws (report.html, wp.html): one HTML file with
// its data in <script type="application/json" id="yardsim-data"> and the bundle inline, so it
// works from file:// with no network.
#include <filesystem>
#include <string>

namespace yardsim::output {

// (title, data as JSON text) => the page
std::string htmlPage(const std::string& title, std::string dataJson);
// (file, page) => written; throws std::runtime_error naming the file when it cannot be
void writeTextFile(const std::filesystem::path& file, const std::string& text);

}  // namespace yardsim::output
