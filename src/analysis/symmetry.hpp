#pragma once
// Mirror images of a half or quarter model. A deck with `symmetry: [x]` simulates the part
// x >= 0 only; measurements of the whole event (a hole straddling the plane, a fragment cut in
// two by it, a cloud's width) are taken on the simulated points together with their images.
#include "core/error.hpp"
#include "core/types.hpp"

#include <utility>
#include <vector>

namespace kessler::analysis {

class Mirror {
 public:
  Mirror() = default;
  // `axes`: the axes normal to mirror planes through the origin (0 = x, 1 = y, 2 = z).
  explicit Mirror(std::vector<int> axes) : axes_(std::move(axes)) {
    for (const int a : axes_) KESSLER_VERIFY(a >= 0 && a <= 2, "symmetry axis {} must be 0, 1 or 2", a);
  }

  // Number of images of a point in the full model (the point itself included): 2^planes.
  int images() const { return 1 << axes_.size(); }
  int planes() const { return static_cast<int>(axes_.size()); }
  int axis(int plane) const { return axes_[plane]; }

  // Image `mask` of x: reflected in plane i when bit i of mask is set. Image 0 is x.
  Vec3 image(Vec3 x, int mask) const {
    for (std::size_t i = 0; i < axes_.size(); ++i)
      if (mask & (1 << i)) x[axes_[i]] = -x[axes_[i]];
    return x;
  }

 private:
  std::vector<int> axes_;
};

}  // namespace kessler::analysis
