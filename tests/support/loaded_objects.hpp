#pragma once
// Which shared objects the test process has loaded: the modules that keep heavy libraries out
// of start-up (output/module_loader.hpp) are checked by what is in memory.
#include <link.h>

#include <cstring>

namespace yardsim::testing {

// (part of a file name) => whether a loaded object's path contains it
inline bool loaded(const char* part) {
  auto visit = [](dl_phdr_info* info, std::size_t, void* data) {
    return info->dlpi_name != nullptr &&
                   std::strstr(info->dlpi_name, static_cast<const char*>(data)) != nullptr
               ? 1
               : 0;
  };
  return dl_iterate_phdr(visit, const_cast<char*>(part)) != 0;
}

}  // namespace yardsim::testing
