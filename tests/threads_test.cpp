// The process-wide thread count.
#include "halfspace/threads.hpp"

#include <gtest/gtest.h>

#include <string>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

TEST(ThreadsTest, SetThreadsIsReportedBack) {
  const int original = threads();
  EXPECT_GE(original, 1);
  set_threads(3);
  EXPECT_EQ(threads(), 3);
  set_threads(original);
  EXPECT_EQ(threads(), original);
}

TEST(ThreadsTest, RejectsFewerThanOne) {
  try {
    set_threads(0);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("thread count 0"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace
