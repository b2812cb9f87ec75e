#include "output/hdf5_file.hpp"

#include <hdf5.h>
#include <stdexcept>

namespace yardsim::output {

namespace {
// (status, what, file) => throws when negative
void check(std::int64_t status, const std::string& what, const std::filesystem::path& file) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what + " in " + file.string());
}
}  // namespace

Hdf5File::Hdf5File(const std::filesystem::path& file) : name_(file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors come back as exceptions, not printed
  file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  check(file_, "create the file", file);
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5File::parents(const std::string& path) {
  for (std::size_t at = path.find('/', 1); at != std::string::npos; at = path.find('/', at + 1))
    group(path.substr(0, at));
}

void Hdf5File::group(const std::string& path) {
  if (path.empty() || path == "/") return;
  if (H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0) return;
  parents(path);
  const hid_t g = H5Gcreate2(file_, path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(g, "create group " + path, name_);
  H5Gclose(g);
}

void Hdf5File::dataset(const std::string& path, std::int64_t type, std::size_t n,
                       const void* data) {
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

void Hdf5File::doubles(const std::string& path, const std::vector<double>& v) {
  dataset(path, H5T_NATIVE_DOUBLE, v.size(), v.data());
}

void Hdf5File::integers(const std::string& path, const std::vector<std::int64_t>& v) {
  dataset(path, H5T_NATIVE_INT64, v.size(), v.data());
}

void Hdf5File::strings(const std::string& path, const std::vector<std::string>& v) {
  std::vector<const char*> ptrs;
  for (const auto& s : v) ptrs.push_back(s.c_str());
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  dataset(path, type, ptrs.size(), ptrs.data());
  H5Tclose(type);
}

void Hdf5File::attribute(const std::string& path, const std::string& name,
                         const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
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

}  // namespace yardsim::output
