#include "isolated_call.hpp"

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>

#if defined(__SANITIZE_ADDRESS__)
#define RKPM_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RKPM_UNDER_ASAN 1
#endif
#endif

// Set by libFuzzer (and any sanitizer runtime) to save the input when the process dies;
// weak, so that a build without them links.
extern "C" __attribute__((weak)) void __sanitizer_set_death_callback(void (*)(void));

namespace rkpm::particles {

std::size_t ByteReader::checked_count(std::size_t unit) {
  const auto n = get<std::uint64_t>();
  if (n > (bytes_.size() - pos_) / unit) throw std::runtime_error("the child's answer is truncated");
  return static_cast<std::size_t>(n);
}

void ByteReader::copy(void* to, std::size_t n) {
  if (n > bytes_.size() - pos_) throw std::runtime_error("the child's answer is truncated");
  if (n > 0) std::memcpy(to, bytes_.data() + pos_, n);
  pos_ += n;
}

namespace {

// The child's answer: a status byte (0 = the result follows, 1 = an error message
// follows), then the bytes.
constexpr char kResult = 0, kError = 1;

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

void apply_limits(const ChildLimits& limits) {
  if (limits.cpu_seconds > 0.0) {
    const auto seconds = static_cast<rlim_t>(limits.cpu_seconds) + 1;
    const rlimit cpu{seconds, seconds + 1};  // soft: SIGXCPU, hard: SIGKILL a second later
    ::setrlimit(RLIMIT_CPU, &cpu);
  }
#ifndef RKPM_UNDER_ASAN
  if (limits.memory_bytes > 0) {
    const rlimit memory{limits.memory_bytes, limits.memory_bytes};
    ::setrlimit(RLIMIT_AS, &memory);
  }
#endif
}

[[noreturn]] void child(int fd, const std::function<void(ByteWriter&)>& work, const ChildLimits& limits) {
  // A crash here is the answer, not the parent's death: it must end the child with its
  // signal. The handlers a host installed would report it as the host's own crash (a
  // fuzzer saves the input as crashing the fuzzed process, Python's faulthandler prints
  // its stack), and so would a sanitizer's death callback.
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(signal, SIG_DFL);
  apply_limits(limits);
  std::string answer;
  try {
    ByteWriter out;
    work(out);
    answer = std::string(1, kResult) + out.bytes();
  } catch (const std::bad_alloc&) {
    answer = std::string(1, kError) + "ran out of the memory it may use (" +
             std::to_string(limits.memory_bytes >> 20) + " MiB)";
  } catch (const std::exception& e) {
    answer = std::string(1, kError) + e.what();
  } catch (...) {
    answer = std::string(1, kError) + "failed with an error of unknown type";
  }
  write_all(fd, answer);
  ::close(fd);
  ::_exit(0);  // no atexit handlers, no flushing of the parent's buffers
}

std::string describe_end(int status, bool timed_out, const ChildLimits& limits) {
  if (timed_out) return "took longer than its wall-clock limit of " + std::to_string(static_cast<long>(2 * limits.cpu_seconds)) + " s";
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    if (signal == SIGXCPU)
      return "took longer than its CPU-time limit of " + std::to_string(static_cast<long>(limits.cpu_seconds)) + " s";
    return std::string("crashed (signal ") + std::to_string(signal) + ", " + ::strsignal(signal) + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return "crashed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  return "ended without an answer";
}

}  // namespace

std::string run_isolated(const std::function<void(ByteWriter&)>& work, const ChildLimits& limits) {
  int fds[2];
  if (::pipe(fds) != 0) throw IsolatedError{std::string("cannot create a pipe: ") + std::strerror(errno)};
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw IsolatedError{std::string("cannot start a child process: ") + std::strerror(errno)};
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], work, limits);
  }
  ::close(fds[1]);

  // Read until the child closes its end, or until the wall clock runs out.
  std::string answer;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::milliseconds(static_cast<long long>(2000.0 * limits.cpu_seconds));
  char buffer[1 << 16];
  for (;;) {
    int wait_ms = -1;
    if (limits.cpu_seconds > 0.0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) {
        timed_out = true;
        break;
      }
      wait_ms = static_cast<int>(std::min<long long>(left.count(), 1 << 30));
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, wait_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline is checked above
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const bool clean = !timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0 && !answer.empty();
  if (!clean) throw IsolatedError{describe_end(status, timed_out, limits)};
  if (answer[0] == kError) throw IsolatedError{answer.substr(1)};
  return answer.substr(1);
}

}  // namespace rkpm::particles
