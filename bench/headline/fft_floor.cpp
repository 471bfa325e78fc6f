// The bare FFT floor of a whole solve: mean wall seconds of one out-of-place
// FFTW r2c + c2r pair of an n x n real array (2n x 2n with --padded, which is
// what a free-boundary n x n grid transforms). Every operator or
// preconditioner application costs at least one such pair, so a solve's
// seconds per iteration over this number says how close it runs to FFTW.
// scripts/headline.sh runs it beside each solve. It times the benchmarks'
// bare pair (bench/bare_fft_pair.hpp, raw FFTW: no halfspace wrapper, no
// wisdom file), so the floor does not move when the library's transforms
// change.
//
//   fft_floor --n N --threads T [--planning estimate|measure|patient] [--padded]
//
// Prints one line of JSON:
//   {"n":1024,"transform_n":1024,"threads":2,"planning":"measure","seconds_per_pair":0.0071}
// Bad arguments: a message naming the argument on stderr, exit code 2.
#include <fftw3.h>
#include <fmt/format.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

#include "bare_fft_pair.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// Long enough that one pair of a small grid is averaged over many runs and
// timer resolution and scheduler noise wash out; at least 5 runs so a large
// grid is not judged by one.
constexpr double kMinSeconds = 0.5;
constexpr long kMinRepetitions = 5;

struct Arguments {
  long n = 0;
  int threads = 0;
  std::string planning = "measure";
  bool padded = false;
};

class ArgumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A whole-string positive integer: "12x" or "-3" are refused, not truncated.
long positive_integer(std::string_view name, const char* text, long limit) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 1 || value > limit) {
    throw ArgumentError(fmt::format("{} {}: expected an integer from 1 to {}", name, text, limit));
  }
  return value;
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--padded") {
      a.padded = true;
      continue;
    }
    if (arg != "--n" && arg != "--threads" && arg != "--planning") {
      throw ArgumentError(fmt::format("{}: unknown argument", arg));
    }
    if (i + 1 >= argc) throw ArgumentError(fmt::format("{}: missing value", arg));
    const char* value = argv[++i];
    if (arg == "--n") {
      a.n = positive_integer(arg, value, 1L << 16);
    } else if (arg == "--threads") {
      a.threads = static_cast<int>(positive_integer(arg, value, 4096));
    } else {
      a.planning = value;
      // The levels `halfspace solve --fft-planning` offers.
      if (a.planning != "estimate" && a.planning != "measure" && a.planning != "patient") {
        throw ArgumentError(fmt::format("--planning {}: expected estimate, measure or patient", value));
      }
    }
  }
  if (a.n == 0) throw ArgumentError("--n: required");
  if (a.threads == 0) throw ArgumentError("--threads: required");
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  try {
    args = parse(argc, argv);
  } catch (const ArgumentError& error) {
    std::fprintf(stderr,
                 "fft_floor: %s\nusage: fft_floor --n N --threads T [--planning estimate|measure|patient] [--padded]\n",
                 error.what());
    return 2;
  }

  // Threads are a property of the plan: fftw_plan_with_nthreads needs the
  // threads initialised, and BareFftPair sets the count before planning.
  if (fftw_init_threads() == 0) {
    std::fprintf(stderr, "fft_floor: fftw_init_threads failed\n");
    return 1;
  }
  const auto m = static_cast<std::size_t>(args.padded ? 2 * args.n : args.n);
  const unsigned flags = args.planning == "patient"   ? FFTW_PATIENT
                         : args.planning == "measure" ? FFTW_MEASURE
                                                      : FFTW_ESTIMATE;
  double seconds_per_pair = 0.0;
  {
    halfspace::bench::BareFftPair pair(2, m, args.threads, flags);  // runs once: warm-up
    long repetitions = 0;
    double elapsed = 0.0;
    const auto start = Clock::now();
    while (elapsed < kMinSeconds || repetitions < kMinRepetitions) {
      pair.run();
      ++repetitions;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    }
    // Read the output so the compiler cannot treat the pairs as unused.
    volatile double sink = pair.data()[0];
    (void)sink;
    seconds_per_pair = elapsed / static_cast<double>(repetitions);
  }

  std::printf("%s\n",
              fmt::format(R"({{"n":{},"transform_n":{},"threads":{},"planning":"{}","seconds_per_pair":{:.6g}}})",
                          args.n, m, args.threads, args.planning, seconds_per_pair)
                  .c_str());
  fftw_cleanup_threads();
  return 0;
}
