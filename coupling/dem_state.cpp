#include "dem_state.hpp"

namespace isphdem {

Mat3 DemBody::inertia_tensor() const {
  Mat3 t{};
  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) t[i][j] += inertia[k] * axes[k][i] * axes[k][j];
  return t;
}

}  // namespace isphdem
