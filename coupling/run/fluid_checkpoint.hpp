#pragma once
// The fluid's part of a checkpoint: every particle array (Particles::for_each_array, in storage
// order) and what the solver carries between steps (isph::StepCarry), as named arrays of this
// process's file (io/checkpoint.hpp).
#include "io/checkpoint.hpp"
#include "isph_solver.hpp"

namespace isphdem {

template <int Dim>
void save_fluid(const isph::IsphSolver<Dim>& solver, CheckpointArrays& arrays);

// Puts the saved fluid back into a solver built from the same case (and decomposed alike).
// std::runtime_error when the file holds another dimension or misses an array.
template <int Dim>
void restore_fluid(isph::IsphSolver<Dim>& solver, const CheckpointArrays& arrays);

}  // namespace isphdem
