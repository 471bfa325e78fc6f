// The preconditioner seam of the EHL GMRES solve (film_krylov_solver.hpp):
// an approximate inverse of the sparse part of the Newton Jacobian (the
// Reynolds stencil's derivatives with K kept near the diagonal), prepared
// once per matrix (`factorise`) and applied once per GMRES iteration
// (`apply`). Two implementations: Eigen's sparse LU (exact, fill growing as
// n^1.5) and a geometric multigrid V-cycle (film_multigrid.hpp). Private to
// the library.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"

namespace halfspace::lubrication::detail {

// A square sparse matrix in compressed rows, columns ascending in each row.
struct CsrMatrix {
  std::size_t rows = 0;
  std::vector<int> start;  // rows + 1 offsets
  std::vector<int> column;
  std::vector<double> value;

  std::size_t entries() const { return column.size(); }
  // Empties the matrix for rows appended one by one.
  void clear();
  // Appends the next row from `entries` (columns in any order, repeated
  // ones summed; every entry kept, zero or not, so that a pattern written
  // in full is the same at every Newton step) and empties `entries`.
  void append_row(std::vector<std::pair<int, double>>& entries);
  // out = b - A x.
  void residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd& out) const;
};

// Appends one row's `entries` (columns in any order, repeated ones summed,
// every entry kept) to `column` and `value`, columns ascending; sorts
// `entries`.
void append_summed(std::vector<std::pair<int, double>>& entries, std::vector<int>& column, std::vector<double>& value);

class FilmPreconditioner {
 public:
  virtual ~FilmPreconditioner() = default;
  // Prepares the approximate inverse of `matrix` (n x n on the film's
  // grid, row k the node k); the matrix must outlive the applications.
  // Returns false with a message when it cannot (a singular factor).
  virtual bool factorise(const CsrMatrix& matrix, std::string& message) = 0;
  // out = M^-1 in, the same linear map for every call until the next
  // factorise (GMRES's right preconditioning needs a fixed one).
  virtual void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) = 0;
};

// The preconditioner of `kind` for matrices on `grid`; `line_axis` (0: x,
// 1: y) is the entrainment's axis, along which the multigrid's line
// relaxation solves.
std::unique_ptr<FilmPreconditioner> make_film_preconditioner(KrylovPreconditioner kind, const Grid& grid,
                                                             int line_axis);

// Bytes per node the preconditioner of `kind` holds for a matrix of
// `row_entries` entries per row (the LU with a fill allowance; the
// multigrid's levels, line factors and work vectors).
double film_preconditioner_bytes_per_node(KrylovPreconditioner kind, double row_entries);

}  // namespace halfspace::lubrication::detail
