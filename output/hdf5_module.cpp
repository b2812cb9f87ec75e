// The module libyardsim_hdf5.so (hdf5_module.hpp): an HDF5 file written through libhdf5's C API.
#include "output/hdf5_module.hpp"

#include <hdf5.h>
#include <stdexcept>

namespace yardsim::output {

namespace {

// (status, what, file) => throws when negative
void check(std::int64_t status, const std::string& what, const std::filesystem::path& file) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what + " in " + file.string());
}

class Hdf5Writer final : public Hdf5Backend {
 public:
  // (file) => created (truncated), or std::runtime_error
  explicit Hdf5Writer(const std::filesystem::path& file) : name_(file) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors come back as exceptions, not printed
    file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    check(file_, "create the file", file);
  }
  ~Hdf5Writer() override {
    if (file_ >= 0) H5Fclose(file_);
  }
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  void group(const std::string& path) override {
    if (path.empty() || path == "/") return;
    if (H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0) return;
    parents(path);
    const hid_t g = H5Gcreate2(file_, path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    check(g, "create group " + path, name_);
    H5Gclose(g);
  }

  void doubles(const std::string& path, const std::vector<double>& v) override {
    dataset(path, H5T_NATIVE_DOUBLE, v.size(), v.data());
  }

  void integers(const std::string& path, const std::vector<std::int64_t>& v) override {
    dataset(path, H5T_NATIVE_INT64, v.size(), v.data());
  }

  void strings(const std::string& path, const std::vector<std::string>& v) override {
    std::vector<const char*> ptrs;
    for (const auto& s : v) ptrs.push_back(s.c_str());
    const hid_t type = utf8();
    dataset(path, type, ptrs.size(), ptrs.data());
    H5Tclose(type);
  }

  void attribute(const std::string& path, const std::string& name,
                 const std::string& value) override {
    const hid_t type = utf8();
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate_by_name(file_, path.c_str(), name.c_str(), type, space, H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT);
    const char* text = value.c_str();
    const herr_t w = a >= 0 ? H5Awrite(a, type, &text) : -1;
    if (a >= 0) H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
    check(w, "write attribute " + name + " of " + path, name_);
  }

 private:
  hid_t file_ = -1;
  std::filesystem::path name_;

  // () => a variable-length UTF-8 string type (the caller closes it)
  static hid_t utf8() {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    return type;
  }

  // (path) => its parent groups created
  void parents(const std::string& path) {
    for (std::size_t at = path.find('/', 1); at != std::string::npos; at = path.find('/', at + 1))
      group(path.substr(0, at));
  }

  // (dataset path, type, count, data) => written
  void dataset(const std::string& path, hid_t type, std::size_t n, const void* data) {
    parents(path);
    const hsize_t dims[1] = {n};
    const hid_t space = H5Screate_simple(1, dims, nullptr);
    const hid_t set =
        H5Dcreate2(file_, path.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Sclose(space);
    check(set, "create dataset " + path, name_);
    const herr_t w = n > 0 ? H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    H5Dclose(set);
    check(w, "write dataset " + path, name_);
  }
};

}  // namespace

}  // namespace yardsim::output

extern "C" void yardsim_hdf5_open(const std::filesystem::path& file,
                                  std::unique_ptr<yardsim::output::Hdf5Backend>& writer) {
  writer = std::make_unique<yardsim::output::Hdf5Writer>(file);
}
