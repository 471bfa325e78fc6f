// The EHL Newton step's linear solve for grids the dense LU cannot hold:
// restarted GMRES (Saad & Schultz 1986) on the Jacobian applied matrix-free
// (the elastic coupling through the influence operator, K never formed),
// right-preconditioned by an approximate inverse of the Jacobian's sparse
// part (the Reynolds stencil with K truncated to a few cells around each
// node): a multigrid V-cycle or a sparse LU (film_preconditioner.hpp).
// Private to the library.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "csr_rows_in_runs.hpp"
#include "film_preconditioner.hpp"
#include "film_slab.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "local_influence.hpp"
#include "restarted_gmres.hpp"
#include "reynolds_linearisation.hpp"

namespace halfspace::lubrication::detail {

struct FilmKrylovSettings {
  int restart = 40;          // GMRES(m) basis size
  int max_iterations = 400;  // GMRES iterations per solve, all restarts
  double tolerance = 1e-9;   // on ||J x + r|| / ||r||
  int neighbourhood = 0;     // K kept within this many cells (Chebyshev) in the preconditioner
  KrylovPreconditioner preconditioner = KrylovPreconditioner::multigrid;

  // Throws OptionError naming the film option (krylov_restart,
  // krylov_max_iterations, krylov_tolerance, preconditioner_neighbourhood)
  // unless 2 <= restart <= 500, max_iterations >= 1, 0 < tolerance < 1 and
  // 0 <= neighbourhood <= 8.
  void validate() const;
};

// The local derivatives of the Newton rows, one row per node of this
// process in CSR form (the terms of detail::linearise, their nodes the
// stencil's: film_slab.hpp), filled by the Newton's linearisation.
struct LocalRows {
  std::vector<std::size_t> start;  // n + 1 offsets into terms
  std::vector<LocalTerm> terms;
};

// Peak bytes the Krylov path needs on an n-node grid (the GMRES basis, the
// local rows, the preconditioner with a fill allowance, the Newton state).
double film_krylov_memory_estimate(std::size_t nodes, const FilmKrylovSettings& settings);

// Rows of the neighbours' each side that a process's block of the
// preconditioner takes in on several processes (film_krylov_solver.cpp).
inline constexpr std::size_t kSlabOverlapRows = 16;

class FilmKrylovSolver {
 public:
  // Reads the translation-invariant K around a node off one product of
  // `op`. `topology` is the stencil of `slab` (this process's rows and
  // their halo); on several processes the preconditioner is a restricted
  // additive Schwarz one (Cai & Sarkis 1999): each process inverts
  // approximately the block of its rows and kSlabOverlapRows rows of its
  // neighbours' each side, and keeps its own rows of the result. Collective
  // on several processes, as solve is.
  FilmKrylovSolver(InfluenceOperator& op, const ReynoldsStencil& topology, const FilmKrylovSettings& settings,
                   const FilmSlab& slab);

  // Solves J step = -residual for the Newton system of the rows `rows`
  // (mass rows over `mass_scale`), the own nodes' branches `branch_full`, the
  // pressure scale dp/ds and the load row's `area / load`, to the relative
  // residual max(settings.tolerance, forcing) (an inexact Newton step).
  // Factorises the preconditioner first; its failure and GMRES's are
  // returned.
  KrylovOutcome solve(const LocalRows& rows, const std::vector<char>& branch_full, double pressure_scale,
                      double mass_scale, double area_over_load, double forcing, const Eigen::VectorXd& residual,
                      Eigen::VectorXd& step);

 private:
  void apply_jacobian(const Eigen::VectorXd& v, Eigen::VectorXd& out);
  bool factorise(std::string& message);
  // On several processes: M^-1 of the block this process's
  // preconditioner inverts (its rows and the overlap) restricted to its
  // own rows.
  void apply_preconditioner(const Eigen::VectorXd& in, Eigen::VectorXd& out);

  InfluenceOperator& op_;
  const ReynoldsStencil& topology_;
  FilmKrylovSettings settings_;
  const FilmSlab& slab_;
  std::size_t n_;         // this process's nodes (the unknowns but h0)
  std::size_t first_;     // the stencil node of the first of them
  LocalInfluence local_;  // K within settings.neighbourhood cells, for the preconditioner
  // The current linear system.
  const LocalRows* rows_ = nullptr;
  double mass_scale_ = 1.0, area_over_load_ = 1.0;
  // dp/ds and dtheta/ds on the stencil; the product's own rows; on several
  // processes v and K dp/ds v on the stencil too.
  Eigen::VectorXd dp_ds_, dtheta_ds_, product_in_, product_out_, v_stencil_, product_stencil_;
  // The preconditioner: B (the n x n sparse part) bordered by the h0
  // column and the load row, solved through M ~ B^-1 and M c.
  CsrMatrix matrix_;
  std::vector<GatheredRowRun> row_runs_;  // the rows being built, per thread
  std::vector<int> row_count_;
  std::unique_ptr<FilmPreconditioner> preconditioner_;
  // On several processes: the overlap's rows below and above, the block's
  // matrix (FilmSlab::gather_rows) and vectors.
  std::size_t below_ = 0, above_ = 0;
  CsrMatrix block_;
  FilmSlab::RowScratch block_scratch_;
  Eigen::VectorXd block_in_, block_out_;
  bool factorised_ = false;  // a factorisation exists (the branches are compared with its load row)
  KrylovNewtonStep krylov_;
};

}  // namespace halfspace::lubrication::detail
