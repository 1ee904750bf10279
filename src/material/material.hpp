#pragma once
// A material law, chosen once per material and run over a whole range of points (never a
// virtual call per point). It never sees the discretisation: it reads each point's F, dF,
// volume and internal variables and writes its stress, specific internal energy and
// longitudinal sound speed.
#include "core/types.hpp"
#include "particles/store.hpp"

#include <memory>
#include <string>

namespace kessler {

class Material {
 public:
  virtual ~Material() = default;
  virtual const std::string& name() const = 0;
  virtual double referenceDensity() const = 0;
  // Longitudinal wave speed of the undeformed material, sqrt((K + 4G/3)/rho0).
  virtual double referenceSoundSpeed() const = 0;
  // Updates the points [begin, end) after their F has been advanced by dF over dt.
  virtual void update(PointStore& points, LocalIndex begin, LocalIndex end, double dt) const = 0;
};

using MaterialPtr = std::shared_ptr<const Material>;

}  // namespace kessler
