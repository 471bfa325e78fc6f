// This process's rows of a film whose influence operator is spread over
// processes in slabs of rows (the distributed operators of mpi/), and the
// halo rows of its neighbours that the Reynolds stencil reaches: the
// Newton solve of the EHL film (elastic_film.cpp) runs on this stencil, so
// that one code serves one process (the whole grid, no halo, every
// reduction the identity) and many (each its slab, halos fetched through
// the operator's linalg::Communicator, sums and extremes reduced). The
// stencil's y edges are fixed-pressure edges of the stencil alone: the
// nodes solved are this process's, whose neighbours all lie in the
// stencil. Private to the library.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "restarted_gmres.hpp"

namespace halfspace::lubrication::detail {

class FilmSlab {
 public:
  // The film on `whole` with `conditions`, of which this process holds
  // `own_nodes` nodes (whole rows, in rank order over `comm`), with `halo`
  // rows of each neighbour. Collective. Throws InputError when the grid is
  // 1D and spread, or some process holds fewer than `halo` rows (then the
  // halo would reach past its neighbour).
  FilmSlab(const Grid& whole, const FlowConditions& conditions, std::size_t own_nodes, const linalg::Communicator& comm,
           std::size_t halo);

  bool distributed() const { return comm_.size() > 1; }
  const linalg::Communicator& communicator() const { return comm_; }
  const Grid& whole_grid() const { return whole_; }
  // The stencil: this process's rows with the halo rows around them.
  const Grid& stencil_grid() const { return stencil_grid_; }
  const FlowConditions& stencil_conditions() const { return stencil_conditions_; }
  // This process's rows as a grid of their own (the whole grid on one
  // process): the preconditioner's.
  const Grid& own_grid() const { return own_grid_; }
  std::size_t stencil_nodes() const { return stencil_grid_.size(); }
  std::size_t own_first() const { return own_first_; }  // the stencil node of this process's first node
  std::size_t own_nodes() const { return own_nodes_; }
  std::size_t first_row() const { return first_row_; }  // this process's first row of the whole grid
  // The whole grid's node of a stencil node.
  std::size_t whole_node(std::size_t stencil_node) const;

  // Fills the halo rows of a stencil field (stencil_nodes() values) from
  // the processes that own them (this process's own rows already in
  // place). Collective; nothing on one process.
  void exchange(double* field) const;

  // Reductions over the processes (the identity on one).
  double sum(double local) const;
  double max(double local) const { return comm_.max(local); }
  double min(double local) const { return comm_.min(local); }
  bool all(bool local) const { return comm_.min(local ? 1.0 : 0.0) > 0.5; }
  // The Euclidean norm of a vector of this process's entries followed by
  // `replicated` entries every process holds alike (h0): those counted
  // once. On one process Eigen's norm, unchanged.
  double norm(Eigen::Ref<const Eigen::VectorXd> v, Eigen::Index replicated) const;
  // The same inner product.
  double dot(Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b, Eigen::Index replicated) const;
  // How the GMRES solve of a Newton step reduces over the processes
  // (nothing on one process: Eigen's products, unchanged).
  KrylovDistribution krylov_distribution() const;

 private:
  void fetch(const double* field, std::size_t whole_first, std::size_t rows, double* into) const;

  Grid whole_;
  const linalg::Communicator& comm_;
  std::size_t first_row_ = 0, own_rows_ = 0, own_first_ = 0, own_nodes_ = 0;
  std::size_t low_halo_ = 0, high_halo_ = 0;
  Grid stencil_grid_, own_grid_;
  FlowConditions stencil_conditions_;
};

}  // namespace halfspace::lubrication::detail
