#include "case/run_settings.hpp"

namespace isphdem {

std::vector<std::string> run_settings_keys() {
  return {"time.end",
          "time.dt",
          "time.max_dt",
          "time.cfl",
          "time.viscous",
          "time.force",
          "output.interval",
          "output.diagnostics_every",
          "output.checkpoint_interval",
          "parallel.decompose"};
}

RunSettings parse_run_settings(const CaseFile& c) {
  RunSettings s;
  s.t_end = c.positive("time.end");
  if (c.has("time.dt")) {
    const auto& n = *c.table().at_path("time.dt").node();
    if (n.is_string()) {
      if (*n.value<std::string>() != "auto")
        throw CaseError("'time.dt' (" + c.where("time.dt") +
                        ") must be a number of seconds or \"auto\"");
    } else {
      s.fixed_dt = c.positive("time.dt");
    }
  }
  s.max_dt = c.positive("time.max_dt", s.max_dt);
  s.limits.cfl = c.positive("time.cfl", s.limits.cfl);
  s.limits.viscous = c.positive("time.viscous", s.limits.viscous);
  s.limits.force = c.positive("time.force", s.limits.force);
  if (s.limits.cfl > 1.0)
    throw CaseError("'time.cfl' = " + std::to_string(s.limits.cfl) +
                    " lets particles move more than one spacing per step: use 0.1-0.5");
  s.output_interval = c.positive("output.interval", s.t_end / 10.0);
  s.diagnostics_every = c.integer("output.diagnostics_every", s.diagnostics_every);
  if (s.diagnostics_every < 1) throw CaseError("'output.diagnostics_every' must be at least 1");
  s.checkpoint_interval =
      c.has("output.checkpoint_interval") ? c.number("output.checkpoint_interval") : s.t_end / 4.0;
  if (!(s.checkpoint_interval >= 0.0))
    throw CaseError(
        "'output.checkpoint_interval' must be 0 (no checkpoints) or a positive number "
        "of simulated seconds");
  if (c.has("parallel.decompose")) s.decompose = c.boolean("parallel.decompose", true);
  return s;
}

}  // namespace isphdem
