#include "devs/model.hpp"

#include "devs/coupled.hpp"

namespace yardsim::devs {

void checkName(std::string_view name, std::string_view what) {
  if (name.empty()) throw ModelError(std::string(what) + " name must not be empty");
  for (char c : name) {
    if (c == '.' || c == ' ' || c == '\t' || c == '\n' || c == '"') {
      throw ModelError(std::string(what) + " name '" + std::string(name) +
                       "' contains '" + std::string(1, c) +
                       "'; names may not contain dots, quotes or white space");
    }
  }
}

std::string PortBase::path() const { return owner_->path() + "." + name_; }

Model::Model(std::string name) : name_(std::move(name)) { checkName(name_, "model"); }

Model::~Model() = default;

std::atomic<std::uint64_t> Model::treeGeneration_{1};

const std::string& Model::path() const {
  const std::uint64_t now = treeGeneration_.load(std::memory_order_relaxed);
  if (path_.empty() || pathGeneration_ != now) {
    const Model* p = parent_;
    path_ = (p && !p->hidden_) ? p->path() + "." + name_ : name_;
    pathGeneration_ = now;
  }
  return path_;
}

PortBase* Model::findPort(std::string_view name) const {
  for (const auto* list : {&in_, &out_})
    for (const auto& p : *list)
      if (p->name() == name) return p.get();
  return nullptr;
}

PortBase& Model::registerPort(std::unique_ptr<PortBase> port,
                              std::vector<std::unique_ptr<PortBase>>& list) {
  checkName(port->name(), "port");
  if (findPort(port->name()))
    throw ModelError("model '" + path() + "' already has a port named '" + port->name() + "'");
  list.push_back(std::move(port));
  return *list.back();
}

}  // namespace yardsim::devs
