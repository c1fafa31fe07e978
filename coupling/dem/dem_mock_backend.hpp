// A DemBackend without LIGGGHTS for unit tests of coupling code: free spheres, no contacts, no
// bodies, exact integration of piecewise-constant loads plus gravity.
#ifndef ISPHDEM_DEM_MOCK_BACKEND_HPP
#define ISPHDEM_DEM_MOCK_BACKEND_HPP

#include <map>

#include "dem/dem_backend.hpp"

namespace isphdem {

class MockDemBackend final : public DemBackend {
 public:
  // atoms: initial tags, positions, velocities, radii (body must be -1).
  MockDemBackend(std::vector<DemAtom> atoms, double dt, double density = 2600.0,
                 Vec3 gravity = {0.0, 0.0, 0.0});

  void initialize(const DemSetup& setup) override;  // records the setup, nothing to run
  const DemState& state() override { return state_; }
  void set_atom_loads(const std::vector<int>& tags, const std::vector<Vec3>& force,
                      const std::vector<Vec3>& torque) override;
  void set_body_loads(const std::vector<int>& ids, const std::vector<Vec3>& force,
                      const std::vector<Vec3>& torque) override;
  void advance(int n_substeps) override;
  double timestep() const override { return dt_; }
  void finalize() override {}

  const DemSetup& setup() const { return setup_; }
  double mass(int tag) const;
  double moment_of_inertia(int tag) const;  // 2/5 m r^2

 private:
  size_t index_of(int tag) const;

  DemState state_;
  double dt_, density_;
  Vec3 gravity_;
  DemSetup setup_;
  std::map<int, size_t> index_;
  std::vector<Vec3> force_, torque_;
};

}  // namespace isphdem

#endif
