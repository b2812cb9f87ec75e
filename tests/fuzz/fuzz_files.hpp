#pragma once
// The fuzz targets' input format: one or more files in one byte string. A line "#@ file NAME"
// starts a file named NAME (letters, digits, '_', '-', '.'; at most 64 characters; no "..");
// bytes before the first such line belong to the first file, named by the caller. Files are
// written into a private folder of this process, emptied before every input. Units: none.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace yardsim::fuzz {

// (input bytes, name of the first file) => (name, content) of each file, the first one first
std::vector<std::pair<std::string, std::string>> splitFiles(const std::uint8_t* data,
                                                            std::size_t size,
                                                            const std::string& firstName);

// (files) => written into this process's private folder (emptied first); its path
std::filesystem::path writeFiles(const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace yardsim::fuzz
