#include "solver/common/mirror.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kessler {

namespace {

// One axis's part of an image: x -> sign x + shift, the slab of space it fills (the whole line when
// it is the identity).
struct AxisImage {
  double sign = 1.0, shift = 0.0;
  double lo = -MirrorBox::none, hi = MirrorBox::none;
  std::size_t inverse = 0;  // the index of the inverse image
};

// The identity first, then the images across a single plane, or between two planes the slabs
// k = -1, 1, -2, 2, ... of width w = hi - lo beside the model's [lo, hi] (slab k is [lo + k w,
// lo + (k + 1) w]: for odd k the model reflected, x -> 2 lo + (k + 1) w - x; for even k translated
// by k w), as far as a point of the model reaches: slab k is at least (|k| - 1) w away.
std::vector<AxisImage> axisImages(double lo, double hi, double reach) {
  std::vector<AxisImage> out(1);
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi) {
    const double w = hi - lo;
    // (More than 127 slabs a side is more than 256 images: refused by the caller, counted here.)
    const int slabs = static_cast<int>(std::min(std::floor(reach / w), 127.0)) + 1;
    for (int n = 1; n <= slabs; ++n)
      for (const int k : {-n, n}) {
        AxisImage i;
        i.lo = lo + k * w;
        i.hi = i.lo + w;
        if (k % 2 != 0) {
          i.sign = -1.0;
          i.shift = 2.0 * lo + (k + 1) * w;
          i.inverse = out.size();
        } else {
          i.shift = k * w;
          i.inverse = k < 0 ? out.size() + 1 : out.size() - 1;  // the translation by -k w beside it
        }
        out.push_back(i);
      }
  } else if (has_lo) {
    out.push_back({-1.0, 2.0 * lo, -MirrorBox::none, lo, 1});
  } else if (has_hi) {
    out.push_back({-1.0, 2.0 * hi, hi, MirrorBox::none, 1});
  }
  return out;
}

}  // namespace

bool MirrorBox::any() const {
  for (int a = 0; a < 3; ++a)
    if (std::isfinite(lo[a]) || std::isfinite(hi[a])) return true;
  return false;
}

Mirrors::Mirrors() : images_(1) {}

Mirrors::Mirrors(const MirrorBox& box, double reach) : box_(box), reach_(reach) {
  KESSLER_VERIFY(std::isfinite(reach) && reach >= 0.0, "mirror planes: the images' reach must be finite, got {}",
                 reach);
  std::array<std::vector<AxisImage>, 3> axes;
  std::size_t total = 1;
  for (int a = 0; a < 3; ++a) {
    KESSLER_VERIFY(!(box.lo[a] >= box.hi[a]),
                   "mirror planes on axis {}: the lower one at {} m is not below the upper one at {} m", "xyz"[a],
                   box.lo[a], box.hi[a]);
    axes[a] = axisImages(box.lo[a], box.hi[a], reach);
    total *= axes[a].size();
  }
  if (total > 256)
    throw Error(
        fmt::format("mirror planes: {} images of the model lie within a kernel's reach of {:.4g} mm (at most 256): "
                    "two planes facing each other are too close for the particles' spacing",
                    total, 1e3 * reach));
  images_.reserve(total);
  for (std::size_t k = 0; k < axes[2].size(); ++k)
    for (std::size_t j = 0; j < axes[1].size(); ++j)
      for (std::size_t i = 0; i < axes[0].size(); ++i) {
        const AxisImage* part[3] = {&axes[0][i], &axes[1][j], &axes[2][k]};
        Image image;
        for (int a = 0; a < 3; ++a) {
          image.sign[a] = part[a]->sign;
          image.shift[a] = part[a]->shift;
          image.lo[a] = part[a]->lo;
          image.hi[a] = part[a]->hi;
          if (part[a]->sign < 0.0) image.flips |= static_cast<std::uint8_t>(1u << a);
        }
        image.inverse = static_cast<std::uint8_t>(
            axes[0][i].inverse + axes[0].size() * (axes[1][j].inverse + axes[1].size() * axes[2][k].inverse));
        images_.push_back(image);
      }
}

Vec3 Mirrors::fold(Vec3 x) const {
  for (int a = 0; a < 3; ++a) {
    const double lo = box_.lo[a], hi = box_.hi[a];
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if (has_lo && has_hi) {
      const double w = hi - lo, period = 2.0 * w;
      double y = std::fmod(x[a] - lo, period);
      if (y < 0.0) y += period;
      x[a] = lo + (y > w ? period - y : y);
    } else if (has_lo && x[a] < lo) {
      x[a] = 2.0 * lo - x[a];
    } else if (has_hi && x[a] > hi) {
      x[a] = 2.0 * hi - x[a];
    }
  }
  return x;
}

}  // namespace kessler
