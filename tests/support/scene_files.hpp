#pragma once
// Test support: real scene files in a fresh temporary folder.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace yardsim::testing {

class SceneDir {
 public:
  SceneDir() {
    std::random_device rd;
    dir_ = std::filesystem::temp_directory_path() /
           ("yardsim-test-" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(dir_);
  }
  ~SceneDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  SceneDir(const SceneDir&) = delete;
  SceneDir& operator=(const SceneDir&) = delete;

  // (name, YAML text) => the file written; its path
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = dir_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }
  const std::filesystem::path& path() const { return dir_; }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

 private:
  std::filesystem::path dir_;
};

}  // namespace yardsim::testing
