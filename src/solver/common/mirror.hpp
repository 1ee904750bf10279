#pragma once
// Mirror planes (docs/theory.md §10, "Mirror planes"): a problem's symmetry planes and its rollers,
// frictionless rigid planes that a particle method sees as mirrors, with the images of its
// particles across them. On axis a the model lies within [lo[a], hi[a]]; an infinite end has no
// plane. Across one plane the image is the model reflected; between two planes that face each
// other the images repeat, each reflected or translated by twice the gap (a hall of mirrors), and
// as many are listed as a kernel's reach needs. Each image is x -> S x + t, S diagonal with entries
// +-1, numbered by a code: 0 the model itself.
#include "core/types.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace kessler {

// A vector reflected across the planes normal to the axes whose bits `flips` sets: multiplied by
// +-1 per axis, which is exact (the same bits as negating), and needs no branch in the kernels'
// loops, which call it for every entry.
inline Vec3 reflect(const Vec3& x, std::uint8_t flips) {
  static constexpr double sign[2] = {1.0, -1.0};
  return Vec3(sign[flips & 1u] * x[0], sign[(flips >> 1) & 1u] * x[1], sign[(flips >> 2) & 1u] * x[2]);
}
// A tensor of the image (R T R with R the reflection): entry (a, b) times the signs of axes a and
// b, exact as for a vector.
inline Mat3 reflect(const Mat3& t, std::uint8_t flips) {
  const Vec3 s = reflect(Vec3(1.0, 1.0, 1.0), flips);
  return t.cwiseProduct(s * s.transpose());
}

// Where the model lies between its mirror planes.
struct MirrorBox {
  static constexpr double none = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{-none, -none, -none};
  std::array<double, 3> hi{none, none, none};
  bool any() const;
  // A free particle that has crossed a plane goes on as its image, which crossed it the other way:
  // its position reflected back into the box and its velocity with it. For debris, which strikes
  // bodies but no other debris, that is exact (docs/theory.md §12, "Kernel updates").
  void reflectInto(Vec3& x, Vec3& v) const {
    for (int a = 0; a < 3; ++a)
      if (x[a] < lo[a]) {
        x[a] = 2.0 * lo[a] - x[a];
        v[a] = -v[a];
      } else if (x[a] > hi[a]) {
        x[a] = 2.0 * hi[a] - x[a];
        v[a] = -v[a];
      }
  }
};

class Mirrors {
 public:
  // No planes: the model alone.
  Mirrors();
  // The images of the model in `box` that any point of the box sees within `reach`. Throws
  // kessler::Error if there would be more than 256 (two planes far closer than the reach).
  Mirrors(const MirrorBox& box, double reach);

  std::size_t count() const { return images_.size(); }
  // The reach the images cover.
  double reach() const { return reach_; }
  const MirrorBox& box() const { return box_; }

  // The image of position x.
  Vec3 point(const Vec3& x, std::uint8_t code) const {
    if (code == 0) return x;
    const Image& i = images_[code];
    return i.sign.cwiseProduct(x) + i.shift;
  }
  // The axes along which the image is reflected (bit a: its component a is reversed): what a vector
  // or a tensor of the image is, by reflect() above.
  std::uint8_t flips(std::uint8_t code) const { return images_[code].flips; }
  Vec3 vector(const Vec3& v, std::uint8_t code) const { return code == 0 ? v : reflect(v, images_[code].flips); }
  Mat3 tensor(const Mat3& t, std::uint8_t code) const { return code == 0 ? t : reflect(t, images_[code].flips); }
  // The code of the inverse transform: if y is x's image by `code`, x is y's by inverse(code) (a
  // reflection is its own inverse, a translation's is the opposite one). It reverses what `code` does
  // to vectors alike.
  std::uint8_t inverse(std::uint8_t code) const { return images_[code].inverse; }

  // f(code) for the model itself (code 0) and each image whose part of space lies within `reach` of
  // x, in the order of their codes. A reach beyond the one the images cover is the caller's error.
  template <class F>
  void near(const Vec3& x, double reach, F&& f) const {
    f(std::uint8_t{0});
    for (std::size_t c = 1; c < images_.size(); ++c) {
      const Image& i = images_[c];
      bool within = true;
      for (int a = 0; a < 3 && within; ++a) within = std::max({i.lo[a] - x[a], x[a] - i.hi[a], 0.0}) < reach;
      if (within) f(static_cast<std::uint8_t>(c));
    }
  }

  // x brought back into the box through the mirrors: a particle that crossed a plane, at the place
  // of its image in the box. No two points are further apart folded than they or their images are.
  Vec3 fold(Vec3 x) const;

 private:
  struct Image {
    Vec3 sign = Vec3::Ones(), shift = Vec3::Zero();
    // The image's part of space (an unreflected axis: everywhere).
    Vec3 lo = Vec3::Constant(-MirrorBox::none), hi = Vec3::Constant(MirrorBox::none);
    std::uint8_t flips = 0;
    std::uint8_t inverse = 0;
  };
  MirrorBox box_;
  double reach_ = 0.0;
  std::vector<Image> images_;
};

}  // namespace kessler
