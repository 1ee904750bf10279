#pragma once
// Three-vectors in the four lanes of an AVX register (the fourth lane unused), for pair loops whose
// terms are 3 x 3: an outer product added to a sum is three fused multiply-adds on whole columns,
// and a matrix times a vector three column operations, where Eigen's 3-vectors take a two-lane and
// a one-lane operation for each. (Loads are masked: none reads past an array. A load of a vector
// just stored waits for the stores: load the data where it lies.) Each lane does what the
// scalar code does to its entry (a product, a difference, a fused multiply-add), so the sums have
// the scalar code's bits; each use was checked so, to the last digit of the verification problems.
// (Not every Eigen expression can be matched: OTM's assembly, f += A g, is compiled with two rows
// in a register and the third contracted in another order, so it stays in Eigen.) Without AVX2
// and FMA the same functions work on Vec3.
#include "core/types.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

namespace kessler::lanes {

#if defined(__AVX2__) && defined(__FMA__)

using V = __m256d;

inline V load(const double* three) {
  return _mm256_maskload_pd(three, _mm256_setr_epi64x(-1, -1, -1, 0));
}
inline V load(const Vec3& v) {
  return load(v.data());
}
inline V zero() {
  return _mm256_setzero_pd();
}
inline Vec3 vec3(V v) {
  alignas(32) double a[4];
  _mm256_store_pd(a, v);
  return {a[0], a[1], a[2]};
}
inline V minus(V a, V b) {
  return _mm256_sub_pd(a, b);
}
inline V times(double s, V v) {
  return _mm256_mul_pd(_mm256_set1_pd(s), v);
}
// (A + B) g, column by column.
inline V sumTimes(const Mat3& A, const Mat3& B, const Vec3& g) {
  const auto column = [&](int c) { return _mm256_add_pd(load(&A(0, c)), load(&B(0, c))); };
  V t = _mm256_mul_pd(column(0), _mm256_set1_pd(g[0]));
  t = _mm256_fmadd_pd(column(1), _mm256_set1_pd(g[1]), t);
  return _mm256_fmadd_pd(column(2), _mm256_set1_pd(g[2]), t);
}

// acc + s v.
inline V plusScaled(V acc, double s, V v) {
  return _mm256_fmadd_pd(_mm256_set1_pd(s), v, acc);
}
// A sum of outer products w g^T, column by column.
class OuterSum {
 public:
  OuterSum() = default;
  explicit OuterSum(const Mat3& start) : c_{load(&start(0, 0)), load(&start(0, 1)), load(&start(0, 2))} {}
  void add(V w, const Vec3& g) {
    c_[0] = _mm256_fmadd_pd(w, _mm256_set1_pd(g[0]), c_[0]);
    c_[1] = _mm256_fmadd_pd(w, _mm256_set1_pd(g[1]), c_[1]);
    c_[2] = _mm256_fmadd_pd(w, _mm256_set1_pd(g[2]), c_[2]);
  }
  void add(V w, V g) {
    c_[0] = _mm256_fmadd_pd(w, _mm256_permute4x64_pd(g, 0x00), c_[0]);
    c_[1] = _mm256_fmadd_pd(w, _mm256_permute4x64_pd(g, 0x55), c_[1]);
    c_[2] = _mm256_fmadd_pd(w, _mm256_permute4x64_pd(g, 0xAA), c_[2]);
  }
  void subtract(V w, V g) {
    c_[0] = _mm256_fnmadd_pd(w, _mm256_permute4x64_pd(g, 0x00), c_[0]);
    c_[1] = _mm256_fnmadd_pd(w, _mm256_permute4x64_pd(g, 0x55), c_[1]);
    c_[2] = _mm256_fnmadd_pd(w, _mm256_permute4x64_pd(g, 0xAA), c_[2]);
  }
  Mat3 matrix() const {
    Mat3 m;
    for (int c = 0; c < 3; ++c) m.col(c) = vec3(c_[c]);
    return m;
  }

 private:
  V c_[3] = {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd()};
};

#else

using V = Vec3;

inline V load(const double* three) {
  return {three[0], three[1], three[2]};
}
inline V load(const Vec3& v) {
  return v;
}
inline V zero() {
  return Vec3::Zero();
}
inline Vec3 vec3(const V& v) {
  return v;
}
inline V minus(const V& a, const V& b) {
  return a - b;
}
inline V times(double s, const V& v) {
  return s * v;
}
inline V sumTimes(const Mat3& A, const Mat3& B, const Vec3& g) {
  return (A.col(0) + B.col(0)) * g[0] + (A.col(1) + B.col(1)) * g[1] + (A.col(2) + B.col(2)) * g[2];
}

inline V plusScaled(const V& acc, double s, const V& v) {
  return acc + s * v;
}

class OuterSum {
 public:
  OuterSum() = default;
  explicit OuterSum(const Mat3& start) : m_(start) {}
  void add(const V& w, const V& g) { m_.noalias() += w * g.transpose(); }
  void subtract(const V& w, const V& g) { m_.noalias() -= w * g.transpose(); }
  Mat3 matrix() const { return m_; }

 private:
  Mat3 m_ = Mat3::Zero();
};

#endif

}  // namespace kessler::lanes
