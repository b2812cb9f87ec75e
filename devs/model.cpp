#include "devs/model.hpp"

#include "devs/coupled.hpp"

namespace yardsim::devs {

namespace {
// (byte) => whether a name may not contain it: '.', ' ', '\t', '\n', '"'
constexpr bool forbidden(unsigned char c) {
  return c == '.' || c == ' ' || c == '\t' || c == '\n' || c == '"';
}
// The same as one 64-bit mask over the bytes below 64 (all the forbidden ones are).
constexpr std::uint64_t kForbiddenMask = [] {
  std::uint64_t m = 0;
  for (unsigned c = 0; c < 64; ++c)
    if (forbidden(static_cast<unsigned char>(c))) m |= std::uint64_t{1} << c;
  return m;
}();
}  // namespace

void checkName(std::string_view name, std::string_view what) {
  if (name.empty()) throw ModelError(std::string(what) + " name must not be empty");
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 64 && ((kForbiddenMask >> u) & 1)) {
      throw ModelError(std::string(what) + " name '" + std::string(name) + "' contains '" +
                       std::string(1, c) + "'; names may not contain dots, quotes or white space");
    }
  }
}

std::string PortBase::path() const {
  return owner_->path() + "." + name_;
}

Model::Model(std::string name) : name_(std::move(name)) {
  checkName(name_, "model");
}

Model::~Model() {
  // (ports) => destroyed; those in the inline store in place, the others freed
  for (PortBase* p : ports_) {
    const auto* at = reinterpret_cast<const std::byte*>(p);
    if (at >= portStore_ && at < portStore_ + kPortStoreBytes)
      p->~PortBase();
    else
      delete p;
  }
}

std::atomic<std::uint64_t> Model::treeGeneration_{1};

const std::string& Model::path() const {
  const std::uint64_t now = treeGeneration_.load(std::memory_order_relaxed);
  if (!path_) path_ = std::make_unique<PathCache>();
  if (path_->path.empty() || path_->generation != now) {
    const Model* p = parent_;
    path_->path = (p && !p->hidden_) ? p->path() + "." + name_ : name_;
    path_->generation = now;
  }
  return path_->path;
}

PortBase* Model::findPort(std::string_view name) const {
  for (PortBase* p : ports_)
    if (p->name() == name) return p;
  return nullptr;
}

void Model::checkNewPort(std::string_view name) const {
  checkName(name, "port");
  if (findPort(name))
    throw ModelError("model '" + path() + "' already has a port named '" + std::string(name) + "'");
}

}  // namespace yardsim::devs
