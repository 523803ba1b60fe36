// Running a library we do not control in a child process: whatever it does with a file
// (crash, allocate without bound, loop, keep broken state), the caller gets the result
// or an error message, never the damage. Used for Gmsh (import_gmsh.cpp), whose readers
// and mesher crash on malformed files and which can mesh without bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rkpm::particles {

// What the child may use. 0 = no limit.
struct ChildLimits {
  double cpu_seconds = 0.0;        // CPU time (RLIMIT_CPU); the wall clock waits twice as long
  std::size_t memory_bytes = 0;    // address space (RLIMIT_AS); not applied under AddressSanitizer,
                                   // whose shadow memory needs terabytes of address space
};

// Bytes written by the child for the parent, and the means to read them back.
class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  template <class T>
  void put_vector(const std::vector<T>& values) {
    put<std::uint64_t>(values.size());
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void put_string(const std::string& text) {
    put<std::uint64_t>(text.size());
    bytes_ += text;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    T value{};
    copy(&value, sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> get_vector() {
    std::vector<T> values(checked_count(sizeof(T)));
    copy(values.data(), values.size() * sizeof(T));
    return values;
  }
  std::string get_string() {
    std::string text(checked_count(1), '\0');
    copy(text.data(), text.size());
    return text;
  }
  // A count of items of at least `unit` bytes each that the rest of the bytes can hold.
  std::size_t checked_count(std::size_t unit);

 private:
  void copy(void* to, std::size_t n);
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

// Runs `work` in a forked child under `limits` and returns the bytes it wrote. A
// std::exception thrown by `work` comes back as IsolatedError with its message; a child
// that is killed (a crash, the CPU limit, the wall clock), exits without answering or
// runs out of memory comes back as IsolatedError saying so. `work` must not use OpenMP
// or MPI: the child has only the forking thread.
struct IsolatedError {
  std::string message;
};
std::string run_isolated(const std::function<void(ByteWriter&)>& work, const ChildLimits& limits);

}  // namespace rkpm::particles
