#include "case/coupling_table.hpp"

namespace isphdem {

std::vector<std::string> coupling_keys() {
  return {"coupling.model",
          "coupling.slab_thickness",
          "coupling.pms_shape",
          "coupling.pms_volume",
          "coupling.pms_overlap",
          "coupling.pms_surface",
          "coupling.auto.resolve_above",
          "coupling.auto.unresolve_below"};
}

std::string coupling_model(const CaseFile& c) {
  const std::string m = c.string("coupling.model", "unresolved");
  if (m != "unresolved" && m != "semi-resolved" && m != "resolved" && m != "auto")
    throw CaseError(
        "'coupling.model' must be \"unresolved\", \"semi-resolved\", \"resolved\" or \"auto\" "
        "(got \"" +
        m + "\")");
  return m;
}

// Defaults: unresolved drag keeps the settling grain's terminal velocity within 1.1% up to
// d/dx = 0.5 and departs beyond (-4.9% at 0.8, -8.6% at 1, -17% at 1.25: docs/study/
// settling_grain.png); PMS bodies are validated from D/dx = 4.8 (the 3D Archimedes clump) to 10
// (the cylinder, docs/resolved.md), and below about 3 particles across a PMS body loses its
// shape. Between 0.5 and 3 neither model is shown accurate: auto says so and keeps such a class
// unresolved (the seed's fines at d/dx = 1 are there).
AutoThresholds auto_thresholds(const CaseFile& c) {
  AutoThresholds t;
  t.resolve_above = c.positive("coupling.auto.resolve_above", t.resolve_above);
  t.unresolve_below = c.positive("coupling.auto.unresolve_below", t.unresolve_below);
  if (t.unresolve_below > t.resolve_above)
    throw CaseError("'coupling.auto.unresolve_below' (" + std::to_string(t.unresolve_below) +
                    ") is above 'coupling.auto.resolve_above' (" + std::to_string(t.resolve_above) +
                    "): it must not be");
  return t;
}

double slab_thickness(const CaseFile& c) {
  if (c.has("coupling.slab_thickness") && c.has("unresolved.slab_thickness"))
    throw CaseError(
        "both 'coupling.slab_thickness' and 'unresolved.slab_thickness' are set: keep one "
        "(coupling.slab_thickness)");
  if (c.has("coupling.slab_thickness")) return c.positive("coupling.slab_thickness");
  if (c.has("unresolved.slab_thickness")) return c.positive("unresolved.slab_thickness");
  throw CaseError(
      "a 2D coupled case needs 'coupling.slab_thickness': the thickness T [m] of the DEM slab "
      "(usually one grain diameter) over which grain volume and forces are spread");
}

}  // namespace isphdem
