// Drives a column that is periodic along the flow at a prescribed mean Darcy velocity, with a
// uniform body force adjusted before every fluid step (the constant-flow-rate drive of periodic
// channel simulations). The seed drives its tank with a forcing zone; in a column periodic in
// the flow direction the zone must hold the whole pressure drop of the bed across its edges,
// and the particles next to it went unstable within 0.03 s (docs/unresolved.md). The body force
// is a pressure gradient that is uniform over the column, so it holds the same drop smoothly.
//
// Case keys: [inflow] mode = "mean_flow", velocity (m/s), direction (default against gravity).
// The control law is proportional-integral, scaled by the predictor's response of the mean
// velocity to the drive, dt <eps/(C_r + dt K)>: g_d = I + k e, k = beta/(dt <eps/(C_r + dt K)>),
// I += gamma k e,
// e = U - <v_D>. The proportional part removes a fraction beta = 0.5 of the error per step;
// the integral part (gamma = 0.05) builds up the steady drive that balances the bed's
// resistance. A pure integral drive oscillated: in clear water the mean velocity integrates
// the drive, and two integrators in a loop ring.
//
// What is held: the particles' mean velocity (flux = "velocity", the default) or the flux the
// particles carry (flux = "particles"): their velocity plus their shift per step. Shifting moves
// particles against a steady flow through a bed (the concentration its velocity field piles up
// ahead of the grains), so the particles pass less than their velocities say: in the resolved
// bed of examples/fixed_bed_3d at d/dx = 8, 0.884 / 0.905 / 0.919 of it at dt = 1e-3 / 5e-4 /
// 2.5e-4 s, and a drive that held the velocities made the bed's drag depend on the step
// (docs/resolved.md, "The resolved fixed bed across fluid steps").
//
// The drive stands for a mean pressure gradient -rho g_d, which the periodic pressure cannot
// carry, so the grains' -grad p V (UnresolvedCoupling) and the bodies' PMS pressure force miss
// its part: after the fluid step every grain and body in the loads gets rho g_d V. Without it a
// bed of porosity n and height L in a column of height H took (1 - n) L / H less than the
// pressure-driven bed at the same flow (12% in examples/fluidization_2d), and lifted late.
#ifndef ISPHDEM_MEAN_FLOW_DRIVE_HPP
#define ISPHDEM_MEAN_FLOW_DRIVE_HPP

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coupling_stage.hpp"

namespace isphdem {

template <int Dim>
class MeanFlowDrive final : public CouplingStage<Dim> {
 public:
  // velocity: the target mean Darcy velocity vector; gravity: the fluid's own body force.
  // count_shifts: hold the flux the particles carry (velocity plus shift / dt).
  MeanFlowDrive(const isph::Vec<Dim>& velocity, const isph::Vec<Dim>& gravity, double dt,
                double density, bool count_shifts = false)
      : target_(velocity),
        gravity_(gravity),
        dt_(dt),
        density_(density),
        count_shifts_(count_shifts) {}

  std::string name() const override { return "mean_flow_drive"; }
  void initialize(const DemState&, isph::IsphSolver<Dim>&) override {}
  void before_fluid_step(const DemState&, isph::IsphSolver<Dim>& solver) override {
    const auto& P = solver.particles();
    isph::Vec<Dim> mean = isph::Vec<Dim>::Zero();
    double gain = 0.0, n = 0.0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] == isph::kWall) continue;
      mean += P.v[i];
      // The predictor's response of v_D to the drive over one step, drag implicit (PorousMedium):
      // dt eps / (C_r + dt K). Without the dt K a resistive bed (dt K = 38 in
      // examples/fixed_bed_3d) had about 40% of its drive after 0.3 s (now within 1% at 0.2 s).
      gain +=
          P.porosity[i] / (isph::virtual_mass_coefficient(P.porosity[i]) + dt_ * P.resistance[i]);
      n += 1.0;
    }
    if (count_shifts_) mean += solver.last_shift_sum() / dt_;
    if (const isph::RowShare* ranks = solver.decomposition()) {  // each process its particles
      double sums[Dim + 2];
      for (int a = 0; a < Dim; ++a) sums[a] = mean[a];
      sums[Dim] = gain;
      sums[Dim + 1] = n;
      ranks->sum_in_place(sums, Dim + 2);
      for (int a = 0; a < Dim; ++a) mean[a] = sums[a];
      gain = sums[Dim];
      n = sums[Dim + 1];
    }
    if (n == 0.0) return;
    mean /= n;
    gain /= n;
    const isph::Vec<Dim> p = kBeta / (dt_ * gain) * (target_ - mean);
    integral_ += kGamma * p;
    drive_ = integral_ + p;
    solver.set_gravity(gravity_ + drive_);
  }
  // Runs after the couplings that filled `loads` (make_coupling_stages puts it last).
  void after_fluid_step(const DemState& dem, const isph::IsphSolver<Dim>&, double,
                        DemLoads& loads) override {
    for (std::size_t k = 0; k < loads.atom_tags.size(); ++k) {
      const DemAtom* a = find_row(dem.atoms, loads.atom_tags[k], &DemAtom::tag);
      if (a) add_drive(4.0 / 3.0 * M_PI * a->radius * a->radius * a->radius, loads.atom_force[k]);
    }
    for (std::size_t k = 0; k < loads.body_ids.size(); ++k) {
      const DemBody* b = find_row(dem.bodies, loads.body_ids[k], &DemBody::id);
      if (b) add_drive(b->volume, loads.body_force[k]);
    }
  }

  const isph::Vec<Dim>& drive() const { return drive_; }
  // The controller's drive and integral (the body force it set is the solver's, saved there).
  void save(StageState& state) const override {
    state["drive"].assign(drive_.data(), drive_.data() + Dim);
    state["integral"].assign(integral_.data(), integral_.data() + Dim);
  }
  void restore(const StageState& state) override {
    const auto d = state.find("drive"), i = state.find("integral");
    if (d == state.end() || i == state.end() || d->second.size() != std::size_t(Dim) ||
        i->second.size() != std::size_t(Dim))
      throw std::runtime_error("mean-flow drive: the checkpoint holds no drive of this dimension");
    for (int a = 0; a < Dim; ++a) {
      drive_[a] = d->second[a];
      integral_[a] = i->second[a];
    }
  }

 private:
  // DemState rows are sorted by atom tag and by body id.
  template <class Row>
  static const Row* find_row(const std::vector<Row>& rows, int key, int Row::*field) {
    auto it = std::lower_bound(rows.begin(), rows.end(), key,
                               [field](const Row& r, int k) { return r.*field < k; });
    return it != rows.end() && (*it).*field == key ? &*it : nullptr;
  }
  void add_drive(double volume, Vec3& force) const {
    for (int a = 0; a < Dim; ++a) force[a] += density_ * drive_[a] * volume;
  }

  static constexpr double kBeta = 0.5, kGamma = 0.05;
  isph::Vec<Dim> target_, gravity_;
  isph::Vec<Dim> drive_ = isph::Vec<Dim>::Zero(), integral_ = isph::Vec<Dim>::Zero();
  double dt_, density_;
  bool count_shifts_;
};

}  // namespace isphdem

#endif
