#include "subprocess.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rkpm::scaling {

ChildOutcome run_self(const std::vector<std::string>& args) {
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fd[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[1]);

  const std::string self = "/proc/self/exe";
  std::vector<char*> argv{const_cast<char*>(self.c_str())};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fd[1]);
  if (spawned != 0) {
    ::close(pipe_fd[0]);
    throw std::runtime_error(std::string("posix_spawn: ") + std::strerror(spawned));
  }

  ChildOutcome out;
  char buffer[4096];
  ssize_t got = 0;
  while ((got = ::read(pipe_fd[0], buffer, sizeof buffer)) != 0) {
    if (got < 0) {
      if (errno == EINTR) continue;
      break;
    }
    out.output.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(pipe_fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) {
    out.ok = WEXITSTATUS(status) == 0;
    out.status = "exit " + std::to_string(WEXITSTATUS(status));
  } else if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    out.status = "killed by signal " + std::to_string(sig) +
                 (sig == SIGKILL ? " (SIGKILL: out of memory?)" : std::string(" (") + strsignal(sig) + ")");
  } else {
    out.status = "ended with wait status " + std::to_string(status);
  }
  return out;
}

}  // namespace rkpm::scaling
