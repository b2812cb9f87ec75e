#include "devs/model.hpp"

#include <array>

#include "devs/coupled.hpp"
#include "devs/model_arena.hpp"

namespace yardsim::devs {

namespace {
// (byte) => whether a name may not contain it: '.', ' ', '\t', '\n', '"'
constexpr bool forbidden(unsigned char c) {
  return c == '.' || c == ' ' || c == '\t' || c == '\n' || c == '"';
}
// The same as a table over every byte value.
constexpr auto kForbidden = [] {
  std::array<std::uint8_t, 256> t{};
  for (unsigned c = 0; c < 256; ++c) t[c] = forbidden(static_cast<unsigned char>(c)) ? 1 : 0;
  return t;
}();

// (a name checkName refuses) => the ModelError saying why; kept out of checkName, whose loop
// then stays a few instructions per byte
[[noreturn, gnu::noinline, gnu::cold]] void refuseName(std::string_view name,
                                                       std::string_view what) {
  if (name.empty()) throw ModelError(std::string(what) + " name must not be empty");
  char bad = name.front();
  for (const char c : name)
    if (forbidden(static_cast<unsigned char>(c))) {
      bad = c;
      break;
    }
  throw ModelError(std::string(what) + " name '" + std::string(name) + "' contains '" +
                   std::string(1, bad) + "'; names may not contain dots, quotes or white space");
}
}  // namespace

void checkName(std::string_view name, std::string_view what) {
  if (name.empty()) refuseName(name, what);
  for (const char c : name)
    if (kForbidden[static_cast<unsigned char>(c)]) refuseName(name, what);
}

std::string PortBase::path() const {
  return owner_->path() + "." + name_;
}

void* Model::operator new(std::size_t size) {
  return ModelArena::allocate(size);
}

void Model::operator delete(void* block, std::size_t size) noexcept {
  ModelArena::release(block, size);
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
