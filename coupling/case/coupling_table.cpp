#include "case/coupling_table.hpp"

namespace isphdem {

std::vector<std::string> coupling_keys() {
  return {"coupling.model", "coupling.slab_thickness", "coupling.pms_shape", "coupling.pms_volume",
          "coupling.pms_overlap"};
}

std::string coupling_model(const CaseFile& c) {
  const std::string m = c.string("coupling.model", "unresolved");
  if (m != "unresolved" && m != "semi-resolved" && m != "resolved")
    throw CaseError(
        "'coupling.model' must be \"unresolved\", \"semi-resolved\" or \"resolved\" (got \"" + m +
        "\")");
  return m;
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
