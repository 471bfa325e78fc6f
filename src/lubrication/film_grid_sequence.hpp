// Grid sequencing for the EHL Newton iteration (nested iteration, Venner &
// Lubrecht 2000, ch. 3 "full multigrid"): the film solved on the grid of
// twice the spacing is interpolated onto the fine grid as its Newton start,
// so that the fine Newton iteration only corrects the discretisation
// difference. Private to the library.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication::detail {

// The Newton iteration of solve_elastic_film on the operator's grid alone
// (no grid sequencing): from `start` if it holds a film of this grid, else
// from the dry contact (elastic_film.cpp).
ElasticFilm solve_film_newton(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                              const LubricantLaws& laws, const ElasticFilmOptions& options, const ElasticFilm* start);

// K on the grid of twice the spacing as seen through a finer operator:
// R K P with P the piecewise-constant prolongation of a coarse pressure
// onto the 2 (1D) or 2 x 2 (2D) fine cells of each coarse cell and R the
// block average of the displacement. Translation invariant when K is, and
// free or periodic as K is, so it serves any fine operator (homogeneous or
// coated) without knowing its kernel; each product costs one fine product.
// `fine` must outlive this operator.
class CoarsenedInfluenceOperator final : public InfluenceOperator {
 public:
  // `coarse` must be solvers::coarser_grid(fine.grid(), ...).
  CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse);

  const Grid& grid() const override { return coarse_; }
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override { return self_influence_; }

 private:
  InfluenceOperator& fine_;
  Grid coarse_;
  std::vector<double> fine_pressure_, fine_displacement_;
  double self_influence_ = 0.0;
};

}  // namespace halfspace::lubrication::detail
