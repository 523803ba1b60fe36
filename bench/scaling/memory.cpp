#include "memory.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace rkpm::scaling {

namespace {

// The value of "Key:   1234 kB" in a /proc file, in bytes.
std::size_t proc_kib(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size() + 1, key + ":") != 0) continue;
    std::istringstream fields(line.substr(key.size() + 1));
    std::size_t kib = 0;
    fields >> kib;
    return kib * 1024;
  }
  return 0;
}

}  // namespace

std::size_t peak_rss_bytes() { return proc_kib("/proc/self/status", "VmHWM"); }
std::size_t available_bytes() { return proc_kib("/proc/meminfo", "MemAvailable"); }

}  // namespace rkpm::scaling
