// How one tangential load step is imposed: the total tangential force
// (Q_x, Q_y) that body 1 exerts on body 2 (N, N/m in 1D), or the rigid
// tangential displacement (delta_x, delta_y) of body 1 relative to body 2
// (m), the tangential approach. A history is a sequence of them, each step
// starting from the state the previous one left (tangential_solver.hpp).
#pragma once

#include <string_view>

namespace halfspace::solvers {

enum class TangentialControl {
  force,         // (Q_x, Q_y), N in 2D, N/m in 1D
  displacement,  // (delta_x, delta_y), m
};

std::string_view to_string(TangentialControl control);

struct TangentialLoading {
  TangentialControl control = TangentialControl::force;
  double x = 0.0;
  double y = 0.0;

  static TangentialLoading force(double qx, double qy = 0.0) { return {TangentialControl::force, qx, qy}; }
  static TangentialLoading displacement(double dx, double dy = 0.0) {
    return {TangentialControl::displacement, dx, dy};
  }
  // Throws InputError naming the control and the component unless both are finite.
  void validate() const;
};

}  // namespace halfspace::solvers

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using solvers::TangentialControl;
using solvers::TangentialLoading;
}  // namespace halfspace
