// A geometric multigrid V-cycle as the EHL GMRES's preconditioner
// (film_preconditioner.hpp): line Gauss–Seidel along the entrainment
// direction as the smoother (each line's band of the matrix solved
// exactly), the lines swept in chains of consecutive lines coloured
// alternately so that the chains of one colour are swept in parallel (the
// result does not depend on the thread count), Galerkin coarse operators
// P^T A P with cell-centred bilinear prolongation P, and a sparse LU on the
// coarsest grid, optionally on the matrix with its unknowns scaled by the
// diagonal (A D^-1). Venner & Lubrecht (2000, "Multilevel Methods in
// Lubrication") solve the EHL film with line relaxation for the same
// reason: where the pressure is high the Poiseuille term vanishes and each
// row is an upwind difference along the flow, which a line solve inverts
// exactly. Private to the library.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "csr_rows_in_runs.hpp"
#include "film_preconditioner.hpp"
#include "halfspace/grid.hpp"

namespace halfspace::lubrication::detail {

class FilmMultigrid final : public FilmPreconditioner {
 public:
  // Levels for matrices on `grid` (row k the node k, row-major (ny, nx));
  // lines along `line_axis` (0: x, 1: y; x on a 1D grid). An axis is
  // coarsened while it has more than kMinCoarsenedCells nodes (and an even
  // number on periodic grids); the grid where neither is, or that has at
  // most kDirectNodes nodes, is solved by a sparse LU (or, above that
  // size, smoothed). With `scale_columns` the hierarchy is built for A
  // D^-1, D = |diag A|, and the V-cycle's result divided by D: on the EHL
  // rows, whose s unknowns are d/dp p_scale in the film and d/d theta in
  // the cavitated zone, it halves the GMRES iterations at 256^2 and 512^2
  // and keeps them flat (docs/development-log.md); on an operator whose
  // diffusion jumps by decades across a line it makes the coarse
  // correction diverge, because the scaled error is then discontinuous.
  FilmMultigrid(const Grid& grid, int line_axis, bool scale_columns);

  bool factorise(const CsrMatrix& matrix, std::string& message) override;
  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) override;

  std::size_t levels() const { return levels_.size(); }
  // Level l's operator after factorise (0: the fine one as scaled; then
  // the Galerkin operators), for tests.
  const CsrMatrix& level_matrix(std::size_t l) const { return *levels_[l].matrix; }
  // Bytes per fine node held besides the fine matrix, for a fine matrix of
  // `row_entries` entries per row.
  static double bytes_per_node(double row_entries);

  static constexpr std::size_t kMinCoarsenedCells = 16;
  static constexpr std::size_t kDirectNodes = 1024;

 private:
  // A node's coarse parents along one axis (cell-centred bilinear: 3/4 from
  // its own coarse cell, 1/4 from the next one on its side) and a coarse
  // node's fine children with the same weights.
  struct Parents {
    int count = 0;
    std::array<int, 2> index{};
    std::array<double, 2> weight{};
  };
  struct Children {
    int count = 0;
    std::array<int, 4> index{};
    std::array<double, 4> weight{};
  };
  struct Axis {
    std::size_t fine = 0, coarse = 0;
    std::vector<Parents> parents;    // per fine index
    std::vector<Children> children;  // per coarse index
  };
  struct Level {
    std::size_t nx = 0, ny = 0;
    const CsrMatrix* matrix = nullptr;
    CsrMatrix own;       // the scaled fine operator A D^-1, or a coarse level's Galerkin operator
    CsrMatrix off_band;  // the entries outside the line bands
    // Rows that hold only their diagonal (fixed-pressure edges): solved by
    // the smoother, and left out of the transfers, so that the coarse
    // grids see them as the fine one does, as held values (interpolating
    // into them would give the coarse problem free edges).
    std::vector<char> fixed;
    int kl = 0, ku = 0;  // the line bands' sub- and superdiagonals
    // The lines cut into chains of consecutive lines, {first, count},
    // coloured alternately: colour c's chains are chains[colour_start[c] ..
    // colour_start[c + 1]), none coupled to another of its colour by the
    // off-band entries.
    std::vector<std::pair<std::size_t, std::size_t>> chains;
    std::vector<std::size_t> colour_start;
    std::vector<double> band;
    std::vector<int> pivots;
    Eigen::VectorXd x, b, r;
    Axis to_coarse_x, to_coarse_y;    // to the next level (unset on the coarsest)
    std::vector<int> node_x, node_y;  // each node's column and row (no division in the Galerkin product)
  };

  std::size_t line_count(const Level& level) const;
  std::size_t line_length(const Level& level) const;
  std::size_t node(const Level& level, std::size_t line, std::size_t t) const;
  bool split_lines(Level& level, std::string& message);
  void chain_lines(Level& level) const;
  static void find_fixed(Level& level);
  void galerkin(const Level& fine, Level& coarse);
  void smooth(Level& level, bool forward);
  void restrict_residual(const Level& fine, Level& coarse) const;
  void prolongate_add(const Level& coarse, Level& fine) const;
  void cycle(std::size_t l);

  bool periodic_;
  bool scale_columns_;
  Eigen::VectorXd column_scale_;  // D: the fine matrix's |diagonal|
  int line_axis_;
  bool direct_coarsest_ = false;
  std::vector<Level> levels_;
  // One line's right-hand side per thread (grown on the first sweep).
  std::vector<double> line_rhs_;
  // A P on one fine line: its nx rows' coarse columns and values.
  struct ProductLine {
    long y = -1;  // the fine line held, or -1
    std::vector<int> start, column;
    std::vector<double> value;
  };
  // The Galerkin product's per-thread scratch: the row accumulators over
  // coarse offsets (P^T (A P)'s and A P's), the A P of the fine lines last
  // used (a coarse line's children span 4), and the thread's rows before
  // they are joined (but the first thread's, written in place).
  struct GalerkinScratch {
    std::vector<double> window, ap_window;
    std::vector<char> touched, ap_touched;
    std::vector<std::pair<int, double>> row_entries;
    std::array<ProductLine, 8> lines;
    std::vector<int> column;
    std::vector<double> value;
  };
  std::vector<GalerkinScratch> galerkin_scratch_;
  std::vector<GatheredRowRun> off_band_runs_;  // split_lines's rows, per thread
  std::vector<int> row_count_;
  Eigen::SparseMatrix<double> coarsest_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> coarsest_lu_;
};

}  // namespace halfspace::lubrication::detail
