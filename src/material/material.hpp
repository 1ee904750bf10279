#pragma once
// A material law, chosen once per material and run over a whole range of points (never a
// virtual call per point). It never sees the discretisation: it reads each point's F, dF,
// volume and internal variables and writes its stress, specific internal energy, the energy
// density that drives eigenerosion, and the signal speed for the time step.
#include "core/types.hpp"
#include "particles/store.hpp"

#include <limits>
#include <memory>
#include <span>
#include <string>

namespace kessler {

class Material {
 public:
  virtual ~Material() = default;
  virtual const std::string& name() const = 0;
  virtual double referenceDensity() const = 0;
  // Critical energy release rate G_c for eigenerosion, J/m^2 (0: the material does not erode).
  virtual double fractureEnergy() const { return 0.0; }
  // Poisson's ratio, for the calibration of eigenerosion's energy-release estimate.
  virtual double poissonRatio() const = 0;
  // Longitudinal wave speed of the undeformed material, sqrt((K + 4G/3)/rho0).
  virtual double referenceSoundSpeed() const = 0;
  // The largest mean tension an intact point of the material bears, Pa (its spall strength or
  // tension cut-off; infinity if it has neither): the solver's numerical pressures may not pull an
  // intact point harder than this (docs/theory.md §4).
  virtual double tensileLimit() const { return std::numeric_limits<double>::infinity(); }
  // Sets the initial state of the points [begin, end) (temperature, internal variables).
  virtual void initialise(PointStore& /*points*/, LocalIndex /*begin*/, LocalIndex /*end*/) const {}
  // Updates the points [begin, end) after their F has been advanced by dF over dt.
  virtual void update(PointStore& points, LocalIndex begin, LocalIndex end, double dt) const = 0;
  // Adds heat[p - begin] joules to each point of [begin, end) before its update: the kinetic energy
  // the velocity transfer took from the points' fluctuations this step (docs/theory.md §4 step 4).
  // A law without a thermal state (an elastic solid, whose energy is its stored energy) takes none.
  virtual void heat(PointStore& /*points*/, LocalIndex /*begin*/, LocalIndex /*end*/,
                    std::span<const double> /*heat*/) const {}
  // Whether heat() takes the heat it is given (a law with a thermal state).
  virtual bool takesHeat() const { return false; }
};

using MaterialPtr = std::shared_ptr<const Material>;

}  // namespace kessler
