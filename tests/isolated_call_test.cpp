#include "../fem/src/isolated_call.h"

#include "meshprep/core/errors.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>

#include <unistd.h>

using meshprep::detail::call_isolated;

TEST(IsolatedCall, ReturnsTheChildsBytes) {
  const auto r = call_isolated([] { return std::string(200000, 'x'); });  // more than a pipe buffer
  EXPECT_FALSE(r.crashed);
  EXPECT_EQ(r.output, std::string(200000, 'x'));
}

TEST(IsolatedCall, ACrashIsReportedNotInherited) {
  const auto r = call_isolated([]() -> std::string { std::abort(); });
  EXPECT_TRUE(r.crashed);
  EXPECT_EQ(r.signal, SIGABRT);
}

TEST(IsolatedCall, AnExitIsReported) {
  const auto r = call_isolated([]() -> std::string { std::_Exit(7); });
  EXPECT_TRUE(r.crashed);
  EXPECT_EQ(r.exit_status, 7);
}

TEST(IsolatedCall, CancellingKillsAChildThatWouldNeverFinish) {
  // The work never returns: if the cancellation did not kill the child, the test would hang
  // (and ctest's timeout would fail it).
  int asked = 0;
  EXPECT_THROW(call_isolated([]() -> std::string { for (;;) pause(); }, [&asked] { return ++asked > 3; }),
               meshprep::Cancelled);
  EXPECT_EQ(asked, 4);
  // Not cancelled: the work's bytes come back as before.
  EXPECT_EQ(call_isolated([] { return std::string("done"); }, [] { return false; }).output, "done");
}
