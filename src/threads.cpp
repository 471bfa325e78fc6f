// The process-wide thread count: OpenMP loops and FFTW plans use the same one.
#include "halfspace/threads.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

// 0 until set_threads is called: then OpenMP's own default is in force.
std::atomic<int> g_threads{0};

// A whole number that is all of `text`, or nothing.
std::optional<long long> whole_number(std::string_view text) {
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// CPUs a cgroup CPU quota allows, rounded up: cgroup v2's cpu.max ("QUOTA
// PERIOD" or "max PERIOD"), else v1's cpu.cfs_quota_us / cpu.cfs_period_us
// (quota -1: none). Only the hierarchy's root files are read, which is the
// container's own cgroup inside a container.
std::optional<int> cpu_quota() {
  const auto ratio = [](double quota, double period) -> std::optional<int> {
    if (!(quota > 0.0 && period > 0.0)) return std::nullopt;
    return static_cast<int>(std::max(1.0, std::ceil(quota / period)));
  };
  if (std::ifstream v2("/sys/fs/cgroup/cpu.max"); v2) {
    std::string quota;
    std::string period;
    v2 >> quota >> period;
    const std::optional<long long> q = whole_number(quota);
    const std::optional<long long> p = whole_number(period);
    if (q && p) return ratio(static_cast<double>(*q), static_cast<double>(*p));
    return std::nullopt;
  }
  std::ifstream quota_file("/sys/fs/cgroup/cpu/cpu.cfs_quota_us");
  std::ifstream period_file("/sys/fs/cgroup/cpu/cpu.cfs_period_us");
  long long quota = -1;
  long long period = 0;
  if (quota_file >> quota && period_file >> period)
    return ratio(static_cast<double>(quota), static_cast<double>(period));
  return std::nullopt;
}

// The first entry of OMP_NUM_THREADS ("4" or "4,2" for nested levels).
std::optional<int> omp_num_threads() {
  const char* given = std::getenv("OMP_NUM_THREADS");
  if (given == nullptr) return std::nullopt;
  std::string_view text(given);
  text = text.substr(0, text.find(','));
  const std::optional<long long> count = whole_number(text);
  if (!count || *count < 1 || *count > max_threads()) return std::nullopt;
  return static_cast<int>(*count);
}

}  // namespace

int hardware_threads() {
  return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

int max_threads() {
  return kThreadsPerHardwareThread * hardware_threads();
}

int default_threads() {
  if (const std::optional<int> asked = omp_num_threads()) return *asked;
  int available = hardware_threads();
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (::sched_getaffinity(0, sizeof(mask), &mask) == 0) available = std::max(1, CPU_COUNT(&mask));
  if (const std::optional<int> quota = cpu_quota()) available = std::min(available, *quota);
  return std::clamp(available, 1, max_threads());
}

void set_threads(int threads) {
  if (threads < 1 || threads > max_threads()) {
    throw InputError(fmt::format("thread count {} is invalid: allowed range is 1 to {} ({} x the {} hardware threads)",
                                 threads, max_threads(), kThreadsPerHardwareThread, hardware_threads()));
  }
  omp_set_num_threads(threads);
  g_threads.store(threads);
}

int threads() {
  const int set = g_threads.load();
  return set > 0 ? set : omp_get_max_threads();
}

}  // namespace halfspace
