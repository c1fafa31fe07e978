#pragma once
// Particle lattices for building scenes. All lattices share one origin convention: points at
// lo + (k + 1/2) dx, so fluid blocks and the walls around them line up with the wall surface
// exactly half a spacing from the nearest particles on either side.
#include <array>
#include <functional>

#include "particles.hpp"

namespace isph {

// Adds a lattice of particles filling [lo, hi]; `keep` (optional) filters positions.
template <int Dim>
std::size_t fill_box(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi, double dx,
                     int32_t kind, const std::function<bool(const Vec<Dim>&)>& keep = {});

// Adds a solid block of wall particles filling [lo, hi] (e.g. an inner wall), with each
// particle's distance to the nearest face and the outward normal of that face.
template <int Dim>
std::size_t add_wall_block(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi,
                           double dx);

// Adds `layers` of wall particles outside the box [lo, hi] on the closed faces, each with its
// distance to the box and the normal pointing into it. Faces are ordered
// (axis 0 low, axis 0 high, axis 1 low, ...). Corners are filled where two closed faces meet.
template <int Dim>
std::size_t add_wall_shell(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi,
                           double dx, int layers, const std::array<bool, 2 * Dim>& closed);

}  // namespace isph
