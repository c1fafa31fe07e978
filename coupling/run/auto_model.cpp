#include "run/auto_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace isphdem {

namespace {

// Classes are told apart by size to 0.1%: the grains of one LIGGGHTS template share it exactly,
// a polydisperse insertion gives a class per size.
long size_key(double d) { return d > 0 ? std::lround(std::log(d) * 1000.0) : 0; }

}  // namespace

AutoChoice choose_model(const DemState& state, double dx, const AutoThresholds& t) {
  std::map<long, GrainClass> clumps, spheres;
  std::map<int, const DemAtom*> by_tag;
  for (const auto& a : state.atoms) by_tag[a.tag] = &a;
  for (const auto& b : state.bodies) {
    // The clump's extent, twice the furthest sphere surface from its centre of mass: the size
    // a sieve (and the fluid lattice across it) sees, also for a flat quasi-2D clump whose
    // volume-equivalent diameter would be much smaller.
    double d = 0.0;
    for (int tag : b.members)
      if (const auto it = by_tag.find(tag); it != by_tag.end()) {
        const auto& a = *it->second;
        const double r = std::sqrt((a.x[0] - b.x[0]) * (a.x[0] - b.x[0]) +
                                   (a.x[1] - b.x[1]) * (a.x[1] - b.x[1]) +
                                   (a.x[2] - b.x[2]) * (a.x[2] - b.x[2]));
        d = std::max(d, 2.0 * (r + a.radius));
      }
    auto& g = clumps[size_key(d)];
    g.clump = true;
    g.diameter = d;
    ++g.count;
  }
  for (const auto& a : state.atoms) {
    if (a.body != -1) continue;
    auto& g = spheres[size_key(2 * a.radius)];
    g.diameter = 2 * a.radius;
    ++g.count;
  }
  AutoChoice choice;
  bool any_clump_resolved = false;
  for (auto& [key, g] : clumps) {
    g.resolved = g.diameter / dx >= t.resolve_above;
    any_clump_resolved = any_clump_resolved || g.resolved;
  }
  // One run resolves all clumps or none: the stages work per model, not per class.
  for (auto& [key, g] : clumps) {
    const double r = g.diameter / dx;
    if (any_clump_resolved && !g.resolved)
      g.note = "resolved with the larger clumps (one model for all clumps), although d/dx < " +
               std::to_string(t.resolve_above).substr(0, 4);
    else if (!any_clump_resolved && r > t.unresolve_below)
      g.note = "between the validated ranges (unresolved up to d/dx " +
               std::to_string(t.unresolve_below).substr(0, 4) + ", resolved from " +
               std::to_string(t.resolve_above).substr(0, 4) + ")";
    g.resolved = any_clump_resolved;
    choice.classes.push_back(g);
  }
  // Free spheres are resolved when every class of them is large enough and no clump class
  // stays unresolved ("resolved" resolves all grains).
  bool spheres_resolved = !spheres.empty() && (clumps.empty() || any_clump_resolved);
  for (const auto& [key, g] : spheres)
    spheres_resolved = spheres_resolved && g.diameter / dx >= t.resolve_above;
  for (auto& [key, g] : spheres) {
    const double r = g.diameter / dx;
    g.resolved = spheres_resolved;
    if (r >= t.resolve_above && !spheres_resolved)
      g.note = "left unresolved with the " +
               std::string(any_clump_resolved || clumps.empty() ? "smaller free spheres"
                                                                : "unresolved clumps") +
               " (one model for all free spheres)";
    else if (r < t.resolve_above && r > t.unresolve_below)
      g.note = "between the validated ranges (unresolved up to d/dx " +
               std::to_string(t.unresolve_below).substr(0, 4) + ", resolved from " +
               std::to_string(t.resolve_above).substr(0, 4) + ")";
    choice.classes.push_back(g);
  }
  if (spheres_resolved || (any_clump_resolved && spheres.empty()))
    choice.model = "resolved";
  else
    choice.model = any_clump_resolved ? "semi-resolved" : "unresolved";
  return choice;
}

std::string describe(const GrainClass& g, double dx) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s d = %.3g mm, d/dx %.2g -> %s, %zu %s",
                g.clump ? "clumps" : "free spheres", 1e3 * g.diameter, g.diameter / dx,
                g.resolved ? "resolved (PMS)" : "unresolved (porosity and drag)", g.count,
                g.clump ? "bodies" : "spheres");
  std::string s = buf;
  if (!g.note.empty()) s += "; " + g.note;
  return s;
}

GrainModels grain_models(const std::string& model) {
  if (model == "semi-resolved") return {1, 0};
  if (model == "resolved") return {1, 1};
  return {0, 0};
}

}  // namespace isphdem
