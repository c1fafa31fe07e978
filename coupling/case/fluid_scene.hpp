#pragma once
// Builds the fluid side of a case: domain, particles (fluid blocks, wall boxes and blocks, initial
// velocity) and the ISPH configuration, from the [case], [domain], [particles], [fluid], [walls],
// [initial] and [solver] tables.
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "isph_solver.hpp"

namespace isphdem {

template <int Dim>
struct FluidScene {
  isph::Domain<Dim> domain;
  isph::Particles<Dim> particles;
  isph::IsphConfig<Dim> config;
};

// Keys of the tables above, for CaseFile::load.
std::vector<std::string> fluid_scene_keys();

// 2 or 3, from case.dimension.
int case_dimension(const CaseFile& c);

template <int Dim>
FluidScene<Dim> build_fluid_scene(const CaseFile& c);

}  // namespace isphdem
