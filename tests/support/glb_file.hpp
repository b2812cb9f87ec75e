#pragma once
// Test support: read a glTF 2.0 binary back, independently of the writer — the 12-byte header,
// the JSON chunk (parsed by yaml-cpp, JSON being YAML), the BIN chunk, and accessors as floats.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace yardsim::testing {

struct GlbFile {
  std::vector<std::uint8_t> bytes;
  std::uint32_t magic = 0, version = 0, length = 0, jsonLength = 0, jsonType = 0, binLength = 0, binType = 0;
  YAML::Node json;
  const std::uint8_t* bin = nullptr;

  explicit GlbFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (bytes.size() < 20) throw std::runtime_error("not a GLB: " + path);
    magic = u32(0), version = u32(4), length = u32(8), jsonLength = u32(12), jsonType = u32(16);
    json = YAML::Load(std::string(bytes.begin() + 20, bytes.begin() + 20 + jsonLength));
    const std::size_t b = 20 + jsonLength;
    if (b + 8 <= bytes.size()) {
      binLength = u32(b), binType = u32(b + 4);
      bin = bytes.data() + b + 8;
    }
  }
  std::uint32_t u32(std::size_t at) const {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);  // little-endian host (x86-64, aarch64)
    return v;
  }
  // (accessor index) => its float components, count * components
  std::vector<float> floats(int accessor) const {
    const YAML::Node a = json["accessors"][accessor];
    const YAML::Node v = json["bufferViews"][a["bufferView"].as<int>()];
    const auto offset = v["byteOffset"].as<std::size_t>(), n = v["byteLength"].as<std::size_t>();
    std::vector<float> out(n / 4);
    std::memcpy(out.data(), bin + offset, n);
    return out;
  }
  // (node index, "translation" | "rotation") => (times, values) of its animation channel
  std::pair<std::vector<float>, std::vector<float>> channel(int node, const std::string& path) const {
    const YAML::Node anim = json["animations"][0];
    for (const auto& c : anim["channels"])
      if (c["target"]["node"].as<int>() == node && c["target"]["path"].as<std::string>() == path) {
        const YAML::Node s = anim["samplers"][c["sampler"].as<int>()];
        return {floats(s["input"].as<int>()), floats(s["output"].as<int>())};
      }
    throw std::runtime_error("no " + path + " channel for node " + std::to_string(node));
  }
  // (body name) => index of the node whose extras.body is that name, or -1
  int bodyNode(const std::string& name) const {
    for (std::size_t i = 0; i < json["nodes"].size(); ++i)
      if (json["nodes"][i]["extras"] && json["nodes"][i]["extras"]["body"].as<std::string>() == name)
        return static_cast<int>(i);
    return -1;
  }
};

}  // namespace yardsim::testing
