#pragma once
// coupling.model = "auto": at start, every grain class (clumps of one volume, free spheres of
// one radius) is resolved or left unresolved by its diameter over the fluid spacing, d/dx
// (thresholds in case/coupling_table.hpp). The classes' choices are then one of the fixed
// models: everything resolved (clumps alone, or every free-sphere class above the threshold
// too) -> "resolved"; clumps resolved and free spheres not -> "semi-resolved"; clumps not
// resolved -> "unresolved". A class that the one model per kind overrules gets a note.
#include <string>
#include <vector>

#include "case/coupling_table.hpp"
#include "dem_state.hpp"
#include "io/dem_snapshot.hpp"

namespace isphdem {

struct GrainClass {
  bool clump = false;     // a multisphere body type, or free spheres
  double diameter = 0.0;  // clumps: their extent (twice the furthest sphere surface) [m]
  std::size_t count = 0;  // bodies or spheres
  bool resolved = false;
  std::string note;  // why, when it is not what d/dx alone says
};

struct AutoChoice {
  std::string model;  // "unresolved", "semi-resolved" or "resolved"
  std::vector<GrainClass> classes;
};

AutoChoice choose_model(const DemState& state, double spacing, const AutoThresholds& t);

// "clumps d = 5.1 mm, d/dx 5.1 -> resolved (PMS), 12 bodies"
std::string describe(const GrainClass& g, double spacing);

// What /dem/model says of clump and free-sphere atoms under a fixed model.
GrainModels grain_models(const std::string& model);

}  // namespace isphdem
