#include "case/fluid_scene.hpp"

#include <cmath>

#include "lattice.hpp"

namespace isphdem {

using isph::Vec;

std::vector<std::string> fluid_scene_keys() {
  return {"case.dimension",
          "case.description",
          "domain.min",
          "domain.max",
          "domain.periodic",
          "particles.spacing",
          "particles.smoothing_ratio",
          "particles.kernel",
          "fluid.density",
          "fluid.viscosity",
          "fluid.gravity",
          "fluid.blocks.min",
          "fluid.blocks.max",
          "walls.layers",
          "walls.slip",
          "walls.boxes.min",
          "walls.boxes.max",
          "walls.boxes.open",
          "walls.blocks.min",
          "walls.blocks.max",
          "initial.velocity",
          "initial.amplitude",
          "solver.alpha_s",
          "solver.min_wall_distance",
          "solver.pocket_solid_fraction",
          "solver.pms_projection",
          "solver.wall_ghosts",
          "solver.density_relaxation_time",
          "solver.free_surface",
          "solver.spread_pin",
          "solver.surface_threshold",
          "solver.shifting",
          "solver.shifting_coefficient",
          "solver.shifting_max",
          "solver.pressure_tolerance",
          "solver.preconditioner",
          "solver.petsc.options",
          "solver.petsc.setup_reuse",
          "solver.max_iterations",
          "solver.surface_detection",
          "solver.surface_divergence",
          "solver.surface_scan",
          "solver.surface_unstable_rows",
          "solver.surface_refill",
          "solver.surface_remesh_rows",
          "solver.surface_remesh_every",
          "solver.surface_remesh_alpha_s",
          "solver.smagorinsky",
          "solver.smagorinsky_constant",
          "inflow.min",
          "inflow.max",
          "inflow.velocity",
          "inflow.direction",
          "inflow.flux",
          "inflow.mode",
          "inflow.ramp"};
}

int case_dimension(const CaseFile& c) {
  const long d = c.integer("case.dimension", 2);
  if (d != 2 && d != 3)
    throw CaseError("'case.dimension' (" + c.where("case.dimension") + ") must be 2 or 3");
  return static_cast<int>(d);
}

namespace {

template <int Dim>
Vec<Dim> to_vec(const std::vector<double>& v) {
  Vec<Dim> out;
  for (int a = 0; a < Dim; ++a) out[a] = v[a];
  return out;
}

template <int Dim>
void check_box(const Vec<Dim>& lo, const Vec<Dim>& hi, const std::string& what) {
  for (int a = 0; a < Dim; ++a)
    if (!(hi[a] > lo[a]))
      throw CaseError("'" + what + "': max must exceed min along every axis (axis " +
                      std::to_string(a) + ")");
}

template <int Dim>
std::array<bool, 2 * Dim> closed_faces(const toml::table& t, const std::string& context) {
  std::array<bool, 2 * Dim> closed;
  closed.fill(true);
  const auto* open = t["open"].as_array();
  if (!t["open"]) return closed;
  const std::string axes = "xyz";
  if (!open) throw CaseError("'" + context + ".open' must be an array like [\"y+\"]");
  for (const auto& el : *open) {
    const auto s = el.value<std::string>();
    bool ok = s && s->size() == 2 && (s->at(1) == '+' || s->at(1) == '-') &&
              axes.find(s->at(0)) != std::string::npos &&
              static_cast<int>(axes.find(s->at(0))) < Dim;
    if (!ok)
      throw CaseError("'" + context +
                      ".open' entries must be faces such as \"y+\" (top) or \"x-\"");
    closed[2 * axes.find(s->at(0)) + (s->at(1) == '+')] = false;
  }
  return closed;
}

}  // namespace

template <int Dim>
FluidScene<Dim> build_fluid_scene(const CaseFile& c, int part, int parts) {
  FluidScene<Dim> s;
  const std::size_t D = Dim;
  auto& cfg = s.config;
  s.particles.keep_part = part;
  s.particles.keep_parts = parts;
  s.split = parts > 1;

  const double dx = c.positive("particles.spacing");
  s.particles.spacing = dx;
  s.particles.volume = std::pow(dx, Dim);
  cfg.smoothing_ratio = c.positive("particles.smoothing_ratio", 1.3);
  try {
    cfg.kernel = isph::kernel_type_from_name(c.string("particles.kernel", "wendland_c2"));
  } catch (const std::invalid_argument& e) {
    throw CaseError(std::string("'particles.kernel': ") + e.what());
  }

  cfg.density = c.positive("fluid.density", 1000.0);
  cfg.viscosity = c.number("fluid.viscosity", 1e-6);
  if (cfg.viscosity < 0) throw CaseError("'fluid.viscosity' must not be negative");
  std::vector<double> g0(D, 0.0);
  if (Dim == 2)
    g0[1] = -9.81;
  else
    g0[2] = -9.81;
  cfg.gravity = to_vec<Dim>(c.numbers("fluid.gravity", D, g0));

  s.domain.lo = to_vec<Dim>(c.numbers("domain.min", D));
  s.domain.hi = to_vec<Dim>(c.numbers("domain.max", D));
  check_box<Dim>(s.domain.lo, s.domain.hi, "domain");
  const auto periodic = c.booleans("domain.periodic", D, std::vector<bool>(D, false));
  for (int a = 0; a < Dim; ++a) s.domain.periodic[a] = periodic[a];
  for (int a = 0; a < Dim; ++a) {
    if (!periodic[a]) continue;
    const double n = s.domain.length()[a] / dx;
    if (std::abs(n - std::round(n)) > 1e-6)
      throw CaseError("periodic axis " + std::to_string(a) + ": domain length " +
                      std::to_string(s.domain.length()[a]) +
                      " m is not a whole number of particle spacings; adjust domain or "
                      "particles.spacing");
  }

  // Wall blocks are placed first so that fluid blocks can leave them out.
  struct Box {
    Vec<Dim> lo, hi;
  };
  std::vector<Box> wall_blocks;
  int i = 0;
  for (const auto* t : c.tables("walls.blocks")) {
    const std::string ctx = "walls.blocks[" + std::to_string(i++) + "]";
    Box b{to_vec<Dim>(table_numbers(*t, "min", D, ctx)),
          to_vec<Dim>(table_numbers(*t, "max", D, ctx))};
    check_box<Dim>(b.lo, b.hi, ctx);
    // No wall particle may see fluid on both sides of a block: its extrapolated pressure and
    // velocity would mix the two sides and couple them through the wall (a still tank with
    // 3-particle inner walls tore apart within 0.1 s). Two kernel supports are needed.
    const double thinnest = (b.hi - b.lo).minCoeff();
    const double needed = 2.0 * (2.0 * cfg.smoothing_ratio * dx);
    if (thinnest < needed - 1e-9)
      throw CaseError("'" + ctx + "' is " + std::to_string(thinnest * 1e3) +
                      " mm thin, less than two kernel supports (" + std::to_string(needed * 1e3) +
                      " mm at this spacing): the two sides would interact through it; make it "
                      "thicker or refine particles.spacing");
    isph::add_wall_block<Dim>(s.particles, b.lo, b.hi, dx);
    wall_blocks.push_back(b);
  }
  const long layers = c.integer("walls.layers", 0);
  const long needed = static_cast<long>(std::ceil(2.0 * cfg.smoothing_ratio - 1e-9));
  i = 0;
  for (const auto* t : c.tables("walls.boxes")) {
    const std::string ctx = "walls.boxes[" + std::to_string(i++) + "]";
    const Vec<Dim> lo = to_vec<Dim>(table_numbers(*t, "min", D, ctx));
    const Vec<Dim> hi = to_vec<Dim>(table_numbers(*t, "max", D, ctx));
    check_box<Dim>(lo, hi, ctx);
    auto closed = closed_faces<Dim>(*t, ctx);
    for (int a = 0; a < Dim; ++a)
      if (periodic[a]) closed[2 * a] = closed[2 * a + 1] = false;
    const int nl = static_cast<int>(layers > 0 ? layers : needed);
    if (nl < needed)
      throw CaseError("'walls.layers' = " + std::to_string(layers) +
                      " is thinner than the kernel support (" + std::to_string(needed) +
                      " layers needed for smoothing_ratio " + std::to_string(cfg.smoothing_ratio) +
                      ")");
    isph::add_wall_shell<Dim>(s.particles, lo, hi, dx, nl, closed);
  }
  const std::string slip = c.string("walls.slip", "no_slip");
  if (slip == "no_slip")
    cfg.wall = isph::WallSlip::NoSlip;
  else if (slip == "free_slip")
    cfg.wall = isph::WallSlip::FreeSlip;
  else
    throw CaseError("'walls.slip' must be \"no_slip\" or \"free_slip\" (got \"" + slip + "\")");

  i = 0;
  const auto blocks = c.tables("fluid.blocks");
  if (blocks.empty())
    throw CaseError("the case has no fluid: add a [[fluid.blocks]] table with min and max");
  for (const auto* t : blocks) {
    const std::string ctx = "fluid.blocks[" + std::to_string(i++) + "]";
    const Vec<Dim> lo = to_vec<Dim>(table_numbers(*t, "min", D, ctx));
    const Vec<Dim> hi = to_vec<Dim>(table_numbers(*t, "max", D, ctx));
    check_box<Dim>(lo, hi, ctx);
    const int64_t before = s.particles.next_id;  // all processes' particles, split or not
    isph::fill_box<Dim>(s.particles, lo, hi, dx, isph::kFluid, [&](const Vec<Dim>& x) {
      for (const auto& b : wall_blocks)
        if ((x.array() >= b.lo.array()).all() && (x.array() <= b.hi.array()).all()) return false;
      return true;
    });
    if (s.particles.next_id == before)
      throw CaseError("'" + ctx + "' holds no particle at spacing " + std::to_string(dx) +
                      " m: make the block at least one spacing wide");
  }

  s.particles.keep_part = 0;  // what is added later (PMS solids) is every process's
  s.particles.keep_parts = 1;
  const std::string init = c.string("initial.velocity", "rest");
  if (init == "taylor_green") {
    // u = -U cos(kx) sin(ky), v = U sin(kx) cos(ky) with k = 2 pi / L (domain length along x).
    const double U = c.number("initial.amplitude", 1.0);
    const double k = 2.0 * M_PI / s.domain.length()[0];
    for (std::size_t n = 0; n < s.particles.size(); ++n) {
      if (s.particles.kind[n] != isph::kFluid) continue;
      const Vec<Dim> x = s.particles.x[n] - s.domain.lo;
      s.particles.v[n].setZero();
      s.particles.v[n][0] = -U * std::cos(k * x[0]) * std::sin(k * x[1]);
      s.particles.v[n][1] = U * std::sin(k * x[0]) * std::cos(k * x[1]);
      s.particles.p[n] =
          -0.25 * cfg.density * U * U * (std::cos(2 * k * x[0]) + std::cos(2 * k * x[1]));
    }
  } else if (init != "rest" && init != "inflow") {
    throw CaseError("'initial.velocity' must be \"rest\", \"taylor_green\" or \"inflow\" (got \"" +
                    init + "\")");
  }

  cfg.alpha_s = c.number("solver.alpha_s", cfg.alpha_s);
  cfg.min_wall_distance = c.number("solver.min_wall_distance", cfg.min_wall_distance);
  cfg.pocket_solid_fraction = c.number("solver.pocket_solid_fraction", cfg.pocket_solid_fraction);
  const std::string pms_projection = c.string("solver.pms_projection", "increment");
  if (pms_projection != "increment" && pms_projection != "fluid")
    throw CaseError(
        "'solver.pms_projection' must be \"increment\" (PMS rows keep the rigid "
        "velocity through a steady projection) or \"fluid\" (they are projected as "
        "fluid, the code before 2026-12-06)");
  cfg.pms_pressure_increment = pms_projection == "increment";
  const std::string ghosts = c.string("solver.wall_ghosts", "linear");
  if (ghosts != "linear" && ghosts != "quadratic")
    throw CaseError(
        "'solver.wall_ghosts' must be \"linear\" (the fluid's velocity extrapolated linearly "
        "through walls and PMS surfaces) or \"quadratic\" (a parabola fitted along the normal, "
        "for gaps a few spacings wide)");
  cfg.quadratic_wall_ghosts = ghosts == "quadratic";
  cfg.density_relaxation_time =
      c.number("solver.density_relaxation_time", cfg.density_relaxation_time);
  if (cfg.density_relaxation_time < 0.0)
    throw CaseError("'solver.density_relaxation_time' must be >= 0 s (0: solver.alpha_s per step)");
  if (!(cfg.pocket_solid_fraction > 0.0))
    throw CaseError(
        "'solver.pocket_solid_fraction' must be positive (a solid share of the kernel support; "
        "1 turns the pocket treatment off)");
  cfg.free_surface = c.boolean("solver.free_surface", cfg.free_surface);
  cfg.spread_pin = c.boolean("solver.spread_pin", cfg.spread_pin);
  cfg.surface.density_ratio = c.number("solver.surface_threshold", cfg.surface.density_ratio);
  if (cfg.surface.density_ratio <= 0 || cfg.surface.density_ratio >= 1)
    throw CaseError("'solver.surface_threshold' must lie between 0 and 1 (a number-density ratio)");
  try {
    cfg.surface.method =
        isph::surface_detection_from_name(c.string("solver.surface_detection", "number_density"));
  } catch (const std::invalid_argument& e) {
    throw CaseError(std::string("'solver.surface_detection': ") + e.what());
  }
  cfg.surface.divergence = c.positive("solver.surface_divergence", Dim == 2 ? 1.5 : 2.4);
  cfg.surface.scan = c.boolean("solver.surface_scan", cfg.surface.scan);
  cfg.surface.unstable_rows = c.boolean("solver.surface_unstable_rows", cfg.surface.unstable_rows);
  cfg.surface_refill = c.boolean("solver.surface_refill", cfg.surface_refill);
  cfg.surface_remesh_rows =
      static_cast<int>(c.integer("solver.surface_remesh_rows", cfg.surface_remesh_rows));
  cfg.surface_remesh_every =
      static_cast<int>(c.integer("solver.surface_remesh_every", cfg.surface_remesh_every));
  cfg.surface_remesh_alpha_s = c.number("solver.surface_remesh_alpha_s", 0.0);
  if (cfg.surface_remesh_alpha_s < 0.0)
    throw CaseError("'solver.surface_remesh_alpha_s' must be >= 0 (0: solver.alpha_s there too)");
  if (cfg.surface_remesh_rows < 0 || cfg.surface_remesh_every < 1)
    throw CaseError(
        "'solver.surface_remesh_rows' must be >= 0 (0: off) and 'solver.surface_remesh_every' "
        ">= 1 (steps between remeshes)");
  cfg.smagorinsky = c.boolean("solver.smagorinsky", cfg.smagorinsky);
  cfg.smagorinsky_constant = c.positive("solver.smagorinsky_constant", cfg.smagorinsky_constant);

  const std::string inflow_mode = c.string("inflow.mode", "zone");
  if (inflow_mode != "zone" && inflow_mode != "mean_flow")
    throw CaseError(
        "'inflow.mode' must be \"zone\" (a forcing zone [min, max]) or \"mean_flow\" "
        "(a body force holding the mean Darcy velocity; coupled periodic columns)");
  if (c.has("inflow") && inflow_mode == "zone") {
    // The seed's forcing zone: fluid inside [min, max] moves at `velocity` (m/s) along
    // `direction` (default: against gravity, i.e. upward).
    isph::ForcingZone<Dim> z;
    z.lo = to_vec<Dim>(c.numbers("inflow.min", D));
    z.hi = to_vec<Dim>(c.numbers("inflow.max", D));
    check_box<Dim>(z.lo, z.hi, "inflow");
    Vec<Dim> dir = -cfg.gravity;
    if (c.has("inflow.direction")) dir = to_vec<Dim>(c.numbers("inflow.direction", D));
    if (!(dir.norm() > 0))
      throw CaseError(
          "'inflow.direction' must be a non-zero vector (or set gravity for \"upward\")");
    z.velocity = c.number("inflow.velocity") * dir.normalized();
    z.ramp = c.number("inflow.ramp", 0.0);
    if (z.ramp < 0.0) throw CaseError("'inflow.ramp' must be >= 0 s (0: full velocity at once)");
    cfg.forcing.push_back(z);
  }
  if (init == "inflow") {
    // A uniform stream at the zone's full velocity (a wind tunnel started at speed): the first
    // projection turns it into the potential flow round the bodies, which saves the spin-up.
    if (cfg.forcing.empty())
      throw CaseError(
          "'initial.velocity = \"inflow\"' starts the fluid at the forcing zone's velocity: add "
          "an [inflow] zone (inflow.mode = \"zone\")");
    for (std::size_t n = 0; n < s.particles.size(); ++n)
      if (s.particles.kind[n] == isph::kFluid) s.particles.v[n] = cfg.forcing.front().velocity;
  }
  cfg.shifting.enabled = c.boolean("solver.shifting", cfg.shifting.enabled);
  cfg.shifting.coefficient = c.number("solver.shifting_coefficient", cfg.shifting.coefficient);
  cfg.shifting.max_fraction = c.number("solver.shifting_max", cfg.shifting.max_fraction);
  cfg.pressure_solver.tolerance =
      c.positive("solver.pressure_tolerance", cfg.pressure_solver.tolerance);
  cfg.pressure_solver.preconditioner =
      c.string("solver.preconditioner", cfg.pressure_solver.preconditioner);
  if (cfg.pressure_solver.preconditioner != "ilut" &&
      cfg.pressure_solver.preconditioner != "ilu0" &&
      cfg.pressure_solver.preconditioner != "jacobi" && cfg.pressure_solver.preconditioner != "amg")
    throw CaseError("'solver.preconditioner' must be \"amg\", \"jacobi\", \"ilu0\" or \"ilut\"");
  // PETSc's own option syntax, handed over as it is ("-ksp_type gmres -ksp_monitor").
  cfg.pressure_solver.backend_options =
      c.string("solver.petsc.options", cfg.pressure_solver.backend_options);
  cfg.pressure_solver.setup_reuse =
      static_cast<int>(c.integer("solver.petsc.setup_reuse", cfg.pressure_solver.setup_reuse));
  if (cfg.pressure_solver.setup_reuse < 1)
    throw CaseError("'solver.petsc.setup_reuse' (" + c.where("solver.petsc.setup_reuse") +
                    ") must be at least 1 (1: a new AMG setup every solve)");
  cfg.pressure_solver.max_iterations =
      static_cast<int>(c.integer("solver.max_iterations", cfg.pressure_solver.max_iterations));
  return s;
}

template FluidScene<2> build_fluid_scene<2>(const CaseFile&, int, int);
template FluidScene<3> build_fluid_scene<3>(const CaseFile&, int, int);

}  // namespace isphdem
