#include "../fem/src/isolated_call.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>

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
