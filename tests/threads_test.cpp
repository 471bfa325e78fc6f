// The process-wide thread count.
#include "halfspace/threads.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
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

// 10,000 threads took minutes to start and join; the cap is a multiple of
// the hardware threads, and the message gives the range.
TEST(ThreadsTest, RejectsMoreThanTheCap) {
  EXPECT_EQ(max_threads(), kThreadsPerHardwareThread * hardware_threads());
  const int original = threads();
  set_threads(max_threads());
  EXPECT_EQ(threads(), max_threads());
  set_threads(original);
  try {
    set_threads(max_threads() + 1);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find(fmt::format("thread count {} is invalid: allowed range is 1 to {}", max_threads() + 1,
                                    max_threads())),
              std::string::npos)
        << error.what();
  }
  EXPECT_EQ(threads(), original);
}

// Sets an environment variable for its lifetime, then restores it.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) saved_ = old;
    ::setenv(name, value, 1);
  }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;
  ~ScopedVariable() {
    if (saved_) {
      ::setenv(name_, saved_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

TEST(ThreadsTest, DefaultIsTheUsableCpusOrOmpNumThreads) {
  {
    const ScopedVariable unset("OMP_NUM_THREADS", "");
    const int usable = default_threads();
    EXPECT_GE(usable, 1);
    EXPECT_LE(usable, hardware_threads());
  }
  {
    const ScopedVariable one("OMP_NUM_THREADS", "1");
    EXPECT_EQ(default_threads(), 1);
  }
  {
    const ScopedVariable nested("OMP_NUM_THREADS", "3,2");  // the outer level's count
    EXPECT_EQ(default_threads(), 3);
  }
  {
    // Beyond the cap, or not a count: ignored, like the runtime ignores it.
    const ScopedVariable huge("OMP_NUM_THREADS", "99999999999");
    EXPECT_LE(default_threads(), hardware_threads());
  }
}

}  // namespace
}  // namespace halfspace
