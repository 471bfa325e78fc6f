// A preconditioner for the mixed film's Newton system (mixed_film_krylov.hpp)
// whose cost grows as the grid: block Gauss–Seidel on the two kinds of rows.
// With t = dp_f + dp_c the total pressure change, the sparse approximation
// of the Jacobian (K truncated to a few cells, as the sparse LU's) reads
//
//   mass rows:            A v_s + F t = r_s      (F = A_h D K / mass scale)
//   open contact rows:    v_q = r_q              (t = dp/ds v_s + P r_q)
//   closed contact rows:  (K t) / H = r_q        (h = 0 imposed)
//
// Smoothed contact rows (mixed_film.cpp) read a v_q + b (K t) / H = r_q;
// those with b > a are taken as closed, with v_q = (t - dp/ds v_s) / P
// putting a H / (b P) on the diagonal of K_CC, the others as open with
// v_q = r_q / a (their b K t / H left to GMRES).
//
// The open rows are eliminated; what remains of the mass rows, M v_s = r_s -
// F t (M = A + F diag(dp/ds) on the open cells), is a Reynolds operator
// with the EHL film's local elastic term, which the EHL film's V-cycle
// (film_multigrid.hpp) inverts approximately; the closed rows are a small
// system on the contact spots' cells, K_CC t_C = H r_q - K_CO t_O, solved
// by a sparse LU (the spots are disjoint and a few percent of the cells, so
// its fill stays local). One application: the spots for v_s = 0, a V-cycle
// on the mass rows, the spots again with the new v_s (a fixed linear map,
// as GMRES's right preconditioning needs). Private to the library.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cstddef>
#include <string>
#include <vector>

#include "film_multigrid.hpp"
#include "film_preconditioner.hpp"
#include "halfspace/grid.hpp"

namespace halfspace::lubrication::detail {

class MixedBlockPreconditioner {
 public:
  // For matrices on `grid` with the V-cycle's lines along `line_axis` (the
  // entrainment's). On several processes `grid` is a slab's block of rows
  // with its overlap (mixed_film_krylov.cpp).
  MixedBlockPreconditioner(const Grid& grid, int line_axis);

  // Prepares the map for the mass rows' M and F (n x n, as above), the
  // truncated K around each node (`near`, row k: K_km for the cells m near
  // k), the closed contact rows, the nodes' dp/ds (0 where cavitated or
  // fixed) and the scales P and H; with smoothed rows also their weights a
  // (`by_q`) and b (`by_film`), else null. F, `near` and dp/ds must outlive
  // the applications. Returns false with a message when the V-cycle's
  // lines or the spots' LU are singular.
  bool factorise(const CsrMatrix& mass, const CsrMatrix& film, const CsrMatrix& near, const std::vector<char>& closed,
                 const Eigen::VectorXd& dp_ds, double pressure_scale, double film_scale,
                 const std::vector<double>* by_q, const std::vector<double>* by_film, std::string& message);

  // out ~ B^-1 in for the 2n rows [mass; contact] and unknowns [s; q].
  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out);

  // Bytes per node besides the two n x n matrices of `row_entries` entries
  // per row (the V-cycle's levels and the work vectors).
  static double bytes_per_node(double row_entries);

 private:
  // t_C from the closed rows for the given v_s (t = dp/ds v_s + P r_q on
  // the open cells around them).
  void solve_spots(const Eigen::VectorXd& in, const Eigen::VectorXd& v_s);

  std::size_t n_;
  FilmMultigrid multigrid_;
  const CsrMatrix* film_ = nullptr;
  const CsrMatrix* near_ = nullptr;
  const Eigen::VectorXd* dp_ds_ = nullptr;
  // The contact rows' weights a and b at the factorisation (the map is
  // kept over Newton steps): (1, 0) open, (0, 1) closed, or the smoothed ones.
  std::vector<double> weight_q_, weight_film_;
  double pressure_ = 1.0, film_scale_ = 1.0;
  std::vector<int> spot_index_;         // per node: its index among the closed cells, or -1
  std::vector<std::size_t> spot_node_;  // the closed cells
  Eigen::SparseMatrix<double> spots_;   // K_CC
  Eigen::SparseLU<Eigen::SparseMatrix<double>> spots_lu_;
  std::vector<Eigen::Triplet<double>> spot_entries_;
  Eigen::VectorXd spot_rhs_, spot_total_, total_, mass_rhs_, v_s_, open_q_;
};

}  // namespace halfspace::lubrication::detail
