// Quasi-2D slabs (DESIGN.md decision 4): the grains are 3D LIGGGHTS spheres and clumps kept in
// one plane. `normal` is the slab normal axis (0, 1, 2 = x, y, z); the two other axes span the
// plane. In-plane motion needs: no translation along the normal and rotation about the normal
// only.
#ifndef ISPHDEM_PLANAR_CONSTRAINT_H
#define ISPHDEM_PLANAR_CONSTRAINT_H

namespace LAMMPS_NS {
class Multisphere;
}

namespace planar {

// Zero the out-of-plane force component and the in-plane torque components.
void project_load(int normal, double* force, double* torque);

// Zero the out-of-plane velocity component and the in-plane angular velocity components.
void project_motion(int normal, double* v, double* omega);

// For every local multisphere body: switch off integration of the out-of-plane force and of
// the in-plane torques (fix multisphere's per-body fflag/tflag, which its integrator honours),
// zero the out-of-plane velocity and in-plane rotation and put the centre on the plane.
// Returns the tag of a body with no principal axis along the normal (which would tumble out of
// plane, because fix multisphere computes omega from angular momentum through the principal
// frame), or -1 if every local body is planar.
int constrain_bodies(LAMMPS_NS::Multisphere& ms, int normal, double plane_coord);

}  // namespace planar

#endif
