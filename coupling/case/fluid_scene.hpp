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
  // The particles are this process's share only (build_fluid_scene's part of parts).
  bool split = false;
};

// Keys of the tables above, for CaseFile::load.
std::vector<std::string> fluid_scene_keys();

// 2 or 3, from case.dimension.
int case_dimension(const CaseFile& c);

// With parts > 1 this process keeps only its share of the particles, those whose id is `part`
// modulo `parts` (isph::Particles::keep_parts), for a fluid decomposed over `parts` processes
// from the start (FluidRun): no process then holds the whole scene. Every check of the case is
// still made on every process alike.
template <int Dim>
FluidScene<Dim> build_fluid_scene(const CaseFile& c, int part = 0, int parts = 1);

}  // namespace isphdem
