// Stage 1 of a step: sort, neighbour lists with the pair geometry (r_ij, W, grad W), and the
// corrected operator weights that every later stage reuses.
#include "isph_solver.hpp"
#include "projection_stability.hpp"

namespace isph {

template <int Dim>
void IsphSolver<Dim>::find_neighbors() {
  const std::vector<int> perm = search_.sort(particles_);
  if (unit_response_.size() == static_cast<Eigen::Index>(perm.size())) {
    Eigen::VectorXd q(unit_response_.size());
    for (std::size_t k = 0; k < perm.size(); ++k) q[k] = unit_response_[perm[k]];
    unit_response_.swap(q);
  }
  if (decomposition_) {
    decomposition_->add_halo(particles_, search_.cutoff());
    linear_solver_->number_globally(decomposition_->numbering());
    unit_solver_->number_globally(decomposition_->numbering());
  }
  const int n = static_cast<int>(particles_.size());
  first_ = blocked_ ? share_->first(n) : 0;
  last_ = blocked_ ? share_->last(n) : n;
  if (decomposition_ && have_q_) {
    // pinned_lambda reads q at the pin's neighbours, some of which may be in the halo.
    unit_response_.conservativeResize(n);
    share_->exchange_rows(unit_response_.data(), sizeof(double), n);
  }
  search_.build(particles_, kernel_, nb_, first_, last_);
}

template <int Dim>
void IsphSolver<Dim>::compute_operator_weights() {
  const int n = static_cast<int>(particles_.size());
  // Walls need no operators; free-surface particles get the robust first-order forms (a
  // one-sided quadratic fit extrapolates). Their neighbours keep the quadratic fit: the Brookshaw
  // Laplacian is not exact for a linear (hydrostatic) field on a truncated support, and still
  // water drifted and blew up after 6000 steps with it.
  operator_mode_.resize(n);
  for (int i = 0; i < n; ++i)
    operator_mode_[i] = particles_.kind[i] == kWall ? 0 : (particles_.surface[i] ? 1 : 2);
  compute_operators(nb_, kernel_.h(), particles_.volume, operator_mode_, op_);
  // Rows next to the surface that would amplify their own divergence are surface rows (see
  // projection_stability.hpp): a surface test that needs the operators, so it runs here and not in
  // detect_free_surface. Under a surface remesh the remeshed rows are the surface.
  if (config_.free_surface && config_.surface.unstable_rows && !remeshes()) {
    double marked =
        mark_unstable_projection_rows(particles_, nb_, op_, first_, last_, kMinProjectionRatio);
    exchange(particles_.surface);
    if (const RowShare* s = block_share()) marked = s->max(marked);  // all recompute, or none
    if (marked > 0.0) {
      for (int i = 0; i < n; ++i)
        if (particles_.surface[i] && operator_mode_[i] == 2) operator_mode_[i] = 1;
      compute_operators(nb_, kernel_.h(), particles_.volume, operator_mode_, op_);
    }
  }
  exchange(op_.order);  // the pin and the uniform source read every row's
}

template void IsphSolver<2>::find_neighbors();
template void IsphSolver<2>::compute_operator_weights();
template void IsphSolver<3>::find_neighbors();
template void IsphSolver<3>::compute_operator_weights();

}  // namespace isph
