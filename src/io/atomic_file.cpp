#include "rkpm/io/atomic_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace rkpm::io {

namespace fs = std::filesystem;

fs::path temporary_path_for(const fs::path& target) {
  fs::path tmp = target;
  tmp += ".tmp";
  return tmp;
}

void replace_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write_to) {
  const fs::path tmp = temporary_path_for(target);
  try {
    write_to(tmp);
    fs::rename(tmp, target);
  } catch (...) {
    std::error_code ignored;  // best effort: the original error is the one to report
    fs::remove(tmp, ignored);
    throw;
  }
}

void write_text_atomically(const fs::path& target, std::string_view text) {
  replace_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", tmp.string()));
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw std::runtime_error(fmt::format("failed writing '{}' (disk full?)", tmp.string()));
  });
}

}  // namespace rkpm::io
