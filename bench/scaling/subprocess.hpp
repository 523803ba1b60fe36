// Runs this program again as a child process: each size of the study gets a fresh
// address space (clean peak-memory figure), and a crash or an out-of-memory kill of
// a big size ends only that size.
#pragma once

#include <string>
#include <vector>

namespace rkpm::scaling {

struct ChildOutcome {
  bool ok = false;      // exited with status 0
  std::string status;   // "exit 3", "killed by signal 9 (SIGKILL: out of memory?)", ...
  std::string output;   // everything it wrote on stdout
};

// Runs /proc/self/exe with `args`; the child's stderr goes to ours (progress, errors).
ChildOutcome run_self(const std::vector<std::string>& args);

}  // namespace rkpm::scaling
