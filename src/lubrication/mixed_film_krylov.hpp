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

#include "film_krylov_solver.hpp"
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
// in CSR form (detail::linearise's terms, one row per node), which nodes are
// on the full-film branch, which contact rows are closed (impose h = 0), and
// how much of each node's film change reaches the Reynolds equation (the
// slope of reynolds_film: 0 on the boundary film, 1 above 1.5 h_b).
struct MixedRows {
  std::vector<std::size_t> start;  // n + 1 offsets into terms
  std::vector<LocalTerm> terms;
  std::vector<double> film_slope;  // dh_R / dh
  // Smoothed contact rows (empty: the min's branches): d row / d q and
  // d row / d (h / H).
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
  MixedKrylovSolver(InfluenceOperator& op, const ReynoldsStencil& topology, const MixedKrylovSettings& settings,
                    bool load_control);

  // K_00: a cell's displacement under unit pressure on itself.
  double self_influence() const { return local_.self(); }

  // Solves J step = -residual (2n + 1 or 2n entries) for the rows `rows`,
  // the branches `branch_full` and `closed` and the scales (whose
  // load_control must be the constructor's), to the relative
  // residual max(settings.tolerance, forcing); from `step` as given with
  // `warm` (a branch pass's step from the last pass's), else from 0. The
  // preconditioner is an earlier solve's while GMRES converges quickly with
  // it (LaggedPreconditioner), else factorised anew; its failure and
  // GMRES's are returned.
  KrylovOutcome solve(const MixedRows& rows, const std::vector<char>& branch_full, const std::vector<char>& closed,
                      const MixedScales& scales, double forcing, const Eigen::VectorXd& residual, Eigen::VectorXd& step,
                      bool warm);

  // The film's change K (dp_f + dp_c) + dh0 (n entries) under `step` on the
  // branches of the last solve: one operator product.
  void film_change(const Eigen::VectorXd& step, Eigen::VectorXd& out);

 private:
  void apply_jacobian(const Eigen::VectorXd& v, Eigen::VectorXd& out);
  bool factorise(std::string& message);

  InfluenceOperator& op_;
  const ReynoldsStencil& topology_;
  MixedKrylovSettings settings_;
  std::size_t n_;
  Eigen::Index m_;        // unknowns: 2n (+ 1 with h0)
  LocalInfluence local_;  // K within settings.neighbourhood cells, for the preconditioner
  // The current linear system.
  const MixedRows* rows_ = nullptr;
  const std::vector<char>* closed_ = nullptr;
  MixedScales scales_;
  Eigen::VectorXd dp_ds_, dtheta_ds_, total_, deflection_;
  // The preconditioner: B (2n x 2n, sparse) bordered by the h0 column and
  // the load row under load control.
  CsrMatrix matrix_;
  std::vector<std::pair<int, double>> row_scratch_, film_scratch_;
  std::unique_ptr<FilmPreconditioner> preconditioner_;
  // The block preconditioner: the mass rows' M and F (n x n).
  CsrMatrix film_matrix_;
  std::unique_ptr<MixedBlockPreconditioner> block_;
  template <class FilmEntry>
  void mass_row(std::size_t k, bool every_entry, FilmEntry&& film_entry);
  bool factorise_block(std::string& message);
  bool factorise_border(std::string& message);
  KrylovNewtonStep krylov_;
};

}  // namespace halfspace::lubrication::detail
