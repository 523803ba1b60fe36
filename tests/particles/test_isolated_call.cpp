// The child process Gmsh runs in (particles/src/isolated_call.hpp): its answer comes
// back whole, and a crash, a CPU-time limit, a memory limit or an exception comes back
// as an IsolatedError saying which, with the parent unharmed.
#include "isolated_call.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <stdexcept>
#include <vector>

namespace rkpm::particles {
namespace {

std::string error_of(const std::function<void(ByteWriter&)>& work, const ChildLimits& limits = {}) {
  try {
    run_isolated(work, limits);
  } catch (const IsolatedError& e) {
    return e.message;
  }
  return "no error";
}

TEST(IsolatedCall, TheChildsAnswerComesBackWhole) {
  std::vector<double> big(300000);
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = 0.5 * static_cast<double>(i);
  const std::string bytes = run_isolated(
      [&](ByteWriter& out) {
        out.put_string("answer");
        out.put_vector(big);  // more than a pipe holds: the parent reads while the child writes
      },
      {});
  ByteReader in(bytes);
  EXPECT_EQ(in.get_string(), "answer");
  EXPECT_EQ(in.get_vector<double>(), big);
  EXPECT_THROW(in.get<int>(), std::runtime_error) << "reading past the answer";
}

TEST(IsolatedCall, AnExceptionComesBackAsItsMessage) {
  EXPECT_EQ(error_of([](ByteWriter&) { throw std::runtime_error("bad file"); }), "bad file");
}

TEST(IsolatedCall, ACrashIsReportedAndTheParentGoesOn) {
  // Under AddressSanitizer a segmentation fault is reported and ends the child with
  // exit status 1 instead of the signal: either way, "crashed".
  EXPECT_EQ(error_of([](ByteWriter&) { std::raise(SIGSEGV); }).rfind("crashed (", 0), 0u);
  EXPECT_EQ(error_of([](ByteWriter&) { std::raise(SIGABRT); }).rfind("crashed (signal 6", 0), 0u);
}

TEST(IsolatedCall, TheCpuTimeLimitEndsALoop) {
  const std::string e = error_of(
      [](ByteWriter&) {
        volatile double x = 0.0;
        for (;;) x = x + 1.0;
      },
      {1.0, 0});
  EXPECT_NE(e.find("took longer than its"), std::string::npos) << e;
}

TEST(IsolatedCall, TheMemoryLimitEndsAnAllocation) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer needs the address space the limit would take away";
#endif
  const std::string e = error_of(
      [](ByteWriter& out) {
        std::vector<char> huge(std::size_t{4} << 30, 1);
        out.put(huge.back());
      },
      {0.0, std::size_t{512} << 20});
  EXPECT_EQ(e, "ran out of the memory it may use (512 MiB)");
}

}  // namespace
}  // namespace rkpm::particles
