// The mixed film's Newton step on grids the dense (2n + 1)^2 LU cannot
// hold, point contacts above all: restarted GMRES (Saad & Schultz 1986) on
// the Jacobian of mixed_film.cpp applied matrix-free (one product of the
// influence operator per iteration, on the total pressure: K is never
// formed), right-preconditioned by a sparse approximation of it (the
// Reynolds stencil and the closed contact rows with K truncated to a few
// cells around each node), inverted approximately by block Gauss–Seidel
// with the EHL film's V-cycle on the mass rows (mixed_block_preconditioner.hpp)
// or exactly by Eigen's SparseLU (film_preconditioner.hpp), and kept across
// solves while GMRES converges quickly with it (restarted_gmres.hpp).
// Private to the library.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "csr_rows_in_runs.hpp"
#include "film_krylov_solver.hpp"
#include "film_slab.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "local_influence.hpp"
#include "mixed_block_preconditioner.hpp"
#include "reynolds_linearisation.hpp"

namespace halfspace::lubrication::detail {

// The EHL film's GMRES settings; `preconditioner` multigrid is the block
// Gauss–Seidel of mixed_block_preconditioner.hpp, sparse_lu B's sparse LU.
using MixedKrylovSettings = FilmKrylovSettings;

// The Newton system's state at one step: the mass rows' local derivatives
// in CSR form (detail::linearise's terms, one row per own node, the terms'
// nodes the stencil's), which nodes are on the full-film branch, which
// contact rows are closed (impose h = 0), and how much of each node's film
// change reaches the Reynolds equation (the slope of reynolds_film: 0 on
// the boundary film, 1 above 1.5 h_b; on the stencil, halo included).
struct MixedRows {
  std::vector<std::size_t> start;  // n + 1 offsets into terms
  std::vector<LocalTerm> terms;
  std::vector<double> film_slope;  // dh_R / dh
  // Smoothed contact rows (empty: the min's branches): d row / d q and
  // d row / d (h / H), on the own nodes.
  std::vector<double> contact_by_q, contact_by_film;
};

// The system's scales: the unknowns are [s, q, h0] with p_f = P max(s, 0),
// p_c = P q; the mass rows are divided by mass_scale, the closed contact rows
// are h / H and the load row (load - w) / w (absent under separation
// control).
struct MixedScales {
  double pressure = 1.0;  // P
  double film = 1.0;      // H
  double mass = 1.0;
  double area_over_load = 0.0;  // dA / w
  bool load_control = true;
};

// Peak bytes the GMRES path needs on an n-node grid.
double mixed_krylov_memory_estimate(std::size_t nodes, const MixedKrylovSettings& settings);

class MixedKrylovSolver {
 public:
  // Reads the translation-invariant K around a node off one product of `op`;
  // the system has the h0 column and load row under load control.
  // `topology` is the stencil of `slab`; the unknowns are this process's
  // [s, q] and h0. On several processes the block preconditioner is a
  // restricted additive Schwarz one, as the EHL film's
  // (film_krylov_solver.hpp), and the sparse LU is refused (InputError).
  // Collective on several processes, as solve is.
  // The GMRES basis lives in `arnoldi` where given (kept across solvers).
  MixedKrylovSolver(InfluenceOperator& op, const ReynoldsStencil& topology, const MixedKrylovSettings& settings,
                    bool load_control, const FilmSlab& slab, ArnoldiStorage* arnoldi = nullptr);

  // K_00: a cell's displacement under unit pressure on itself.
  double self_influence() const { return local_.self(); }

  // Solves J step = -residual (2n + 1 or 2n entries) for the rows `rows`,
  // the own nodes' branches `branch_full` and `closed` and the scales (whose
  // load_control must be the constructor's), to the relative
  // residual max(settings.tolerance, forcing); from `step` as given with
  // `warm` (a branch pass's step from the last pass's), else from 0. The
  // preconditioner is an earlier solve's while GMRES converges quickly with
  // it (LaggedPreconditioner), else factorised anew; its failure and
  // GMRES's are returned.
  KrylovOutcome solve(const MixedRows& rows, const std::vector<char>& branch_full, const std::vector<char>& closed,
                      const MixedScales& scales, double forcing, const Eigen::VectorXd& residual, Eigen::VectorXd& step,
                      bool warm);

  // The film's change K (dp_f + dp_c) + dh0 (n entries, the own nodes')
  // under `step` on the branches of the last solve: one operator product.
  void film_change(const Eigen::VectorXd& step, Eigen::VectorXd& out);

 private:
  void apply_jacobian(const Eigen::VectorXd& v, Eigen::VectorXd& out);
  void apply_preconditioner(const Eigen::VectorXd& in, Eigen::VectorXd& out);
  bool factorise(std::string& message);
  template <class SEntry, class FilmEntry>
  void mass_row(std::size_t k, bool every_entry, SEntry&& s_entry, FilmEntry&& film_entry) const;
  void mass_rows_border();
  bool factorise_block(std::string& message);
  bool factorise_border(std::string& message);

  InfluenceOperator& op_;
  const ReynoldsStencil& topology_;
  MixedKrylovSettings settings_;
  const FilmSlab& slab_;
  std::size_t n_;         // this process's nodes
  std::size_t first_;     // the stencil node of the first of them
  Eigen::Index m_;        // unknowns: 2n (+ 1 with h0)
  LocalInfluence local_;  // K within settings.neighbourhood cells, for the preconditioner
  // The current linear system.
  const MixedRows* rows_ = nullptr;
  const std::vector<char>* closed_ = nullptr;
  MixedScales scales_;
  // dp/ds, dtheta/ds and the closed rows (1 or 0) on the stencil; the
  // product's own rows; on several processes v_s and the film's change on
  // the stencil too.
  Eigen::VectorXd dp_ds_, dtheta_ds_, closed_stencil_, total_, deflection_, v_stencil_, deflection_stencil_;
  // Per local term of the rows: its stencil node, d/ds there and d/d(the
  // film's change) there, on the current branches.
  std::vector<int> term_node_;
  std::vector<double> term_by_s_, term_by_deflection_;
  // The preconditioner: B (2n x 2n, sparse) bordered by the h0 column and
  // the load row under load control.
  CsrMatrix matrix_;
  std::vector<std::pair<int, double>> row_scratch_;  // the sparse LU's rows, one at a time
  std::vector<GatheredRowRun> row_runs_;             // the block's rows, per thread
  std::vector<int> row_count_;
  std::unique_ptr<FilmPreconditioner> preconditioner_;
  // The block preconditioner: the mass rows' M and F and the truncated K
  // around each node (n x n, columns whole-grid nodes).
  CsrMatrix film_matrix_, near_;
  std::unique_ptr<MixedBlockPreconditioner> block_;
  // On several processes, the block of this process's rows with the
  // overlap: its rows below and above, M, F and K near each node, the
  // nodes' closed rows, dp/ds and smoothed weights, and its vectors.
  std::size_t below_ = 0, above_ = 0;
  CsrMatrix block_mass_, block_film_, block_near_;
  FilmSlab::RowScratch block_scratch_;
  std::vector<double> node_data_, block_node_data_;
  std::vector<char> block_closed_;
  Eigen::VectorXd block_dp_ds_;
  std::vector<double> block_by_q_, block_by_film_;
  Eigen::VectorXd block_in_, block_out_;
  KrylovNewtonStep krylov_;
};

}  // namespace halfspace::lubrication::detail
