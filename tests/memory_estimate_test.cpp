// The memory estimate's arithmetic and the reading of the available memory
// from /proc and cgroup files (fake trees here; the estimate against real
// runs is in tests/apps/memory_estimate_cli_test.cpp).
#include "halfspace/memory_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/hdf5_test_support.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

TEST(MemoryEstimateTest, PerCellCostsMatchTheMeasuredRanges) {
  // docs/performance.md: 70-86 B per cell for periodic 2D solves with
  // pk-multilevel, 100-120 for free ones; the estimate adds the writing of
  // the file (up to two uncompressed images) and stays within 1.5x of those.
  const solvers::SolverOptions settings;
  const auto per_cell = [&](Boundary boundary) {
    const Grid grid = Grid::plane(4096, 4096, 1e-6, 1e-6, boundary);
    return (solve_memory_estimate(grid, settings) - kProgramBytes) / static_cast<double>(grid.size());
  };
  EXPECT_GT(per_cell(Boundary::periodic), 86.0);
  EXPECT_LT(per_cell(Boundary::periodic), 1.5 * 86.0);
  EXPECT_GT(per_cell(Boundary::free), 120.0);
  EXPECT_LT(per_cell(Boundary::free), 1.5 * 120.0);
}

TEST(MemoryEstimateTest, SweepsAndDenseSolversCostMore) {
  const Grid grid = Grid::line(4096, 1e-6, Boundary::free);
  solvers::SolverOptions settings;
  const double one = solve_memory_estimate(grid, settings, 1);
  // Each kept step: three fields, cluster sizes, the residual history and
  // its part of the file image.
  EXPECT_GT(solve_memory_estimate(grid, settings, 11) - one, 10 * 3 * 8.0 * 4096);
  settings.type = solvers::SolverType::lemke;
  // Five dense 4096 x 4096 matrices.
  EXPECT_GT(solve_memory_estimate(grid, settings), 5 * 8.0 * 4096 * 4096);
}

TEST(MemoryEstimateTest, LargestGridsGiveFiniteEstimates) {
  // 2^57 cells, near the grid limit: the estimate must count it without
  // overflow (bytes are doubles; 100 B per cell is past 2^63) and come out
  // near 2^57 * 100.
  const Grid grid = Grid::plane(std::size_t{1} << 29, std::size_t{1} << 28, 1e-6, 1e-6, Boundary::free);
  const double estimate = solve_memory_estimate(grid, solvers::SolverOptions{});
  EXPECT_TRUE(std::isfinite(estimate));
  EXPECT_GT(estimate, 100.0 * std::pow(2.0, 57));
  EXPECT_GT(generate_memory_estimate(grid), 24.0 * std::pow(2.0, 57));
}

TEST(MemoryEstimateTest, SlabsShareTheFieldsAndTheDeflationsFlagsUpToAHalo) {
  // 2048^2 on two processes of 1024 rows each. Without deflation a slab
  // needs about half the one-process estimate (the program's own bytes
  // aside); with deflation (32-cell blocks) every process holds its share
  // of the contact flags and cell lists, plus a halo of at most three block
  // rows (1 + 3 x 8 B per cell) and two more flags per held cell.
  const Grid grid = Grid::plane(2048, 2048, 1e-6, 1e-6, Boundary::periodic);
  solvers::SolverOptions plain;
  plain.deflation.mode = solvers::DeflationOptions::Mode::off;
  solvers::SolverOptions deflated;
  deflated.deflation.mode = solvers::DeflationOptions::Mode::on;
  ASSERT_EQ(deflated.deflation.block, 32U);
  const double whole = slab_solve_memory_estimate(grid, plain, 2048);
  const double half = slab_solve_memory_estimate(grid, plain, 1024);
  EXPECT_GT(half, 0.5 * whole);
  EXPECT_LT(half, 0.6 * whole);
  // The deflation's part of a slab of `rows` rows.
  auto deflation = [&](std::size_t rows) {
    return slab_solve_memory_estimate(grid, deflated, rows) - slab_solve_memory_estimate(grid, plain, rows);
  };
  const double halo = 25.0 * 3.0 * 32.0 * 2048.0 + 2.0 * (1024.0 + 3.0 * 32.0) * 2048.0;
  EXPECT_GE(deflation(1024), 0.5 * deflation(2048) + halo - 1.0);
  EXPECT_LE(deflation(1024), 0.5 * deflation(2048) + halo + 1.0);
  // On eight processes a slab's deflation is about a sixth of the whole
  // grid's (whole-grid flags and lists on every process would make it four
  // fifths).
  EXPECT_LT(deflation(256), 0.2 * deflation(2048));
}

TEST(MemoryEstimateTest, SlabSweepKeepsItsRowsOfEveryStepAndEveryStepsClusterSizes) {
  // A 5-step sweep on 2048^2: each process keeps its rows of the 4 finished
  // steps' three fields (24 B per cell of its share) and every step's
  // cluster sizes whole (at most 4 B per cell of the grid), so the excess
  // over a single solve shrinks with the slab but not below the clusters.
  const Grid grid = Grid::plane(2048, 2048, 1e-6, 1e-6, Boundary::periodic);
  solvers::SolverOptions plain;
  plain.deflation.mode = solvers::DeflationOptions::Mode::off;
  const double cells = static_cast<double>(grid.size());
  EXPECT_EQ(slab_solve_memory_estimate(grid, plain, 1024), slab_solve_memory_estimate(grid, plain, 1024, 1));
  const double half_excess =
      slab_solve_memory_estimate(grid, plain, 1024, 5) - slab_solve_memory_estimate(grid, plain, 1024);
  const double quarter_excess =
      slab_solve_memory_estimate(grid, plain, 512, 5) - slab_solve_memory_estimate(grid, plain, 512);
  EXPECT_GE(half_excess, 4.0 * (0.5 * 24.0 + 4.0) * cells);
  EXPECT_GE(quarter_excess, 4.0 * (0.25 * 24.0 + 4.0) * cells);
  EXPECT_LT(quarter_excess, half_excess);
}

TEST(MemoryEstimateTest, SlabAdhesionOnAFreeGridCountsItsSecondPaddedTransform) {
  // The adhesive energy's form on a free grid: the serial one transforms
  // the whole padded grid once; on slabs (slab_spectral_transforms.cpp) the
  // padding rows go through a second pruned padded transform (2ny complex
  // values per column), so one process holding every row needs that much
  // more than the serial solve.
  const Grid grid = Grid::plane(1024, 512, 1e-6, 1e-6, Boundary::free);
  solvers::SolverOptions settings;
  settings.adhesion = solvers::SolverOptions::Adhesion{AdhesionLaw::maugis_dugdale(0.05, 1e-8), 1e-6, false};
  const double second_transform = 16.0 * 2.0 * 512.0 * (1024.0 + 1.0);
  EXPECT_GE(slab_solve_memory_estimate(grid, settings, 512) - solve_memory_estimate(grid, settings), second_transform);
}

TEST(MemoryEstimateTest, AvailableMemoryIsMemAvailableWithoutACgroupLimit) {
  const TempDir dir;
  write(dir / "proc" / "meminfo", "MemTotal:       24683656 kB\nMemFree:  100 kB\nMemAvailable:   2000 kB\n");
  write(dir / "proc" / "self" / "cgroup", "0::/\n");
  write(dir / "cgroup" / "memory.max", "max\n");
  const std::optional<AvailableMemory> available = available_memory(dir / "proc", dir / "cgroup");
  ASSERT_TRUE(available);
  EXPECT_EQ(available->bytes, 2000.0 * 1024);
  EXPECT_EQ(available->source, "MemAvailable in /proc/meminfo");
}

TEST(MemoryEstimateTest, CgroupV2LimitAlongThePathWins) {
  const TempDir dir;
  write(dir / "proc" / "meminfo", "MemAvailable:   20000000 kB\n");
  write(dir / "proc" / "self" / "cgroup", "0::/jobs/job1\n");
  // The job's own cgroup is unlimited; its parent allows 1 GiB, of which
  // 300 MiB are used, 100 MiB of them reclaimable page cache.
  write(dir / "cgroup" / "jobs" / "job1" / "memory.max", "max\n");
  write(dir / "cgroup" / "jobs" / "memory.max", "1073741824\n");
  write(dir / "cgroup" / "jobs" / "memory.current", "314572800\n");
  write(dir / "cgroup" / "jobs" / "memory.stat", "anon 1000\ninactive_file 104857600\n");
  const std::optional<AvailableMemory> available = available_memory(dir / "proc", dir / "cgroup");
  ASSERT_TRUE(available);
  EXPECT_EQ(available->bytes, (1024.0 - 300.0 + 100.0) * 1048576.0);
  EXPECT_NE(available->source.find("jobs/memory.max"), std::string::npos) << available->source;
}

TEST(MemoryEstimateTest, CgroupV1LimitIsRead) {
  const TempDir dir;
  write(dir / "proc" / "meminfo", "MemAvailable:   20000000 kB\n");
  write(dir / "proc" / "self" / "cgroup", "5:cpu,cpuacct:/\n4:memory:/batch/7\n0::/\n");
  write(dir / "cgroup" / "memory" / "batch" / "7" / "memory.limit_in_bytes", "536870912\n");
  write(dir / "cgroup" / "memory" / "batch" / "7" / "memory.usage_in_bytes", "0\n");
  // The root's "no limit" (2^63 rounded to a page) is ignored.
  write(dir / "cgroup" / "memory" / "memory.limit_in_bytes", "9223372036854771712\n");
  const std::optional<AvailableMemory> available = available_memory(dir / "proc", dir / "cgroup");
  ASSERT_TRUE(available);
  EXPECT_EQ(available->bytes, 536870912.0);
  EXPECT_NE(available->source.find("memory.limit_in_bytes"), std::string::npos) << available->source;
}

TEST(MemoryEstimateTest, NothingKnownGivesNothing) {
  const TempDir dir;
  EXPECT_FALSE(available_memory(dir / "proc", dir / "cgroup"));
}

TEST(MemoryEstimateTest, BytesAreShownInBinaryUnits) {
  EXPECT_EQ(format_bytes(512.0), "512 B");
  EXPECT_EQ(format_bytes(16.0 * 1048576.0), "16 MiB");
  EXPECT_EQ(format_bytes(1.5 * 1073741824.0), "1.5 GiB");
  EXPECT_EQ(format_bytes(93.1 * 1099511627776.0), "93.1 TiB");
}

}  // namespace
}  // namespace halfspace
