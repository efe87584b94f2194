#pragma once
// Numeric types shared by the whole engine.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "physics/core/Trig.h"

#include <cstring>

namespace phasebox {

using Vec = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

inline Vec2 perp(const Vec2& v) {
    return {-v.y(), v.x()};
}
inline double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}
// The very same numbers, bit for bit: one memcmp where Eigen's == compares element by element
// (a −0 against a +0, or a NaN against itself, reads as different).
inline bool sameBits(const Vec& a, const Vec& b) {
    return a.size() == b.size() &&
           (a.size() == 0 || std::memcmp(a.data(), b.data(),
                                         static_cast<std::size_t>(a.size()) * sizeof(double)) == 0);
}
inline Mat2 rotation(double angle) {
    const CosSin t = cosSin(angle);
    Mat2 r;
    r << t.c, -t.s, t.s, t.c;
    return r;
}

}  // namespace phasebox
