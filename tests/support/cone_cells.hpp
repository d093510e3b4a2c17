// The cone of directions a light subtends at a point o, from first principles and independent of
// apse: planar ellipses, spheres and ellipsoids all subtend an elliptic cone {w : wᵀ C w <= 0},
// whose section by the gnomonic plane {w : w·z0 = 1} is an ellipse. ConeCells splits that ellipse
// into equal-area rings × sectors and integrates over each cell in solid angle
// (dω = dA / (1 + |x|²)^{3/2} on the gnomonic plane, a smooth density), which gives the expected
// counts of a chi-square test and the reference values of Monte Carlo tests for every light shape.
// Everything is in double (or long double), from the light's parameters only.
#pragma once

#include "map_testing.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <vector>

namespace apse_test {

/// Symmetric 3×3 cone matrix: the directions w from o that hit the light satisfy wᵀ C w <= 0
/// (together with w·z0 > 0, z0 a direction inside the cone, which removes the opposite nappe).
using ConeMatrix = glm::dmat3;

/// Cone of the planar ellipse {c + s a + t b : s² + t² <= 1} seen from o (a, b independent, not
/// necessarily orthogonal). A ray o + t w meets the plane at the point with coordinates (s, t) in
/// the basis (a, b); multiplied by n·w they are linear in w: (n·w) s = g_s·w, (n·w) t = g_t·w, so
/// the inside is (g_s·w)² + (g_t·w)² <= (n·w)².
inline ConeMatrix cone_of_ellipse(const glm::dvec3& o, const glm::dvec3& c, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 n = glm::cross(a, b);
    const glm::dvec3 a_dual = glm::cross(b, n) / glm::dot(a, glm::cross(b, n));
    const glm::dvec3 b_dual = glm::cross(n, a) / glm::dot(b, glm::cross(n, a));
    const glm::dvec3 d = o - c;
    const double h = glm::dot(n, c - o);
    const glm::dvec3 gs = glm::dot(a_dual, d) * n + h * a_dual;
    const glm::dvec3 gt = glm::dot(b_dual, d) * n + h * b_dual;
    return glm::outerProduct(gs, gs) + glm::outerProduct(gt, gt) - glm::outerProduct(n, n);
}

/// Cone of the solid quadric (p − c)ᵀ M (p − c) <= 1 seen from o outside it: the ray o + t w
/// touches it where the discriminant (wᵀ M d)² − (wᵀ M w)(dᵀ M d − 1), d = o − c, vanishes.
inline ConeMatrix cone_of_quadric(const glm::dvec3& o, const glm::dvec3& c, const glm::dmat3& m) {
    const glm::dvec3 d = o - c, md = m * d;
    return (glm::dot(d, md) - 1.0) * m - glm::outerProduct(md, md);
}

/// M of the ellipsoid with mutually orthogonal semi-axis vectors a1, a2, a3 (a sphere: three
/// orthogonal axes of length r).
inline glm::dmat3 ellipsoid_matrix(const glm::dvec3& a1, const glm::dvec3& a2, const glm::dvec3& a3) {
    glm::dmat3 m(0.0);
    for (const glm::dvec3& a : {a1, a2, a3}) m += glm::outerProduct(a, a) / (glm::dot(a, a) * glm::dot(a, a));
    return m;
}

/// The cone's section by the gnomonic plane through o + z0 (z0 a unit direction inside the cone),
/// written x = q + L y with |y| <= 1 (x: coordinates along e1, e2 in the plane), split into
/// `rings` equal-area rings (in |y|²) × `sectors` sectors.
struct ConeCells {
    glm::dvec3 e1, e2, z0;
    glm::dvec2 q;
    glm::dmat2 l, l_inv;
    int rings = 10, sectors = 16;
    bool valid = false;  ///< false if the section is not a bounded ellipse (z0 not inside, ...)

    ConeCells(const ConeMatrix& cone, const glm::dvec3& axis, int rings_, int sectors_)
        : z0(glm::normalize(axis)), rings(rings_), sectors(sectors_) {
        const glm::dvec3 helper = std::fabs(z0.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        e1 = glm::normalize(glm::cross(helper, z0));
        e2 = glm::cross(z0, e1);
        // x = (x1, x2): w = x1 e1 + x2 e2 + z0, wᵀ C w = xᵀ A x + 2 bᵀ x + k0
        const double a11 = glm::dot(e1, cone * e1), a12 = glm::dot(e1, cone * e2), a22 = glm::dot(e2, cone * e2);
        const double b1 = glm::dot(e1, cone * z0), b2 = glm::dot(e2, cone * z0), k0 = glm::dot(z0, cone * z0);
        const double det = a11 * a22 - a12 * a12;
        if (!(a11 > 0 && det > 0)) return;
        q = glm::dvec2(-(a22 * b1 - a12 * b2) / det, -(a11 * b2 - a12 * b1) / det);  // -A⁻¹ b
        const double k = k0 + b1 * q.x + b2 * q.y;  // value at the centre: k0 − bᵀ A⁻¹ b
        if (!(k < 0)) return;
        // A = Rᵀ R (Cholesky, R upper triangular); inside: |R (x − q)|² <= −k, so L = sqrt(−k) R⁻¹
        const double r11 = std::sqrt(a11), r12 = a12 / r11, r22 = std::sqrt(a22 - r12 * r12), s = std::sqrt(-k);
        // glm matrices are column-major: dmat2(col0, col1)
        const glm::dmat2 r(glm::dvec2(r11, 0.0), glm::dvec2(r12, r22));
        l_inv = r / s;
        l = glm::inverse(l_inv);
        valid = true;
    }

    int count() const { return rings * sectors; }

    /// Cell index of the direction w (any length), -1 if outside the ellipse by more than
    /// `slack` (relative, in |y|²) or behind the plane.
    int cell_of(const glm::dvec3& w, double slack = 1e-9) const {
        const double wz = glm::dot(w, z0);
        if (!(wz > 0)) return -1;
        const glm::dvec2 y = l_inv * (glm::dvec2(glm::dot(w, e1), glm::dot(w, e2)) / wz - q);
        const double rho2 = glm::dot(y, y);
        if (!(rho2 <= 1 + slack)) return -1;
        int ring = int(std::fmin(rho2, 1.0) * rings);
        if (ring >= rings) ring = rings - 1;
        double ang = std::atan2(y.y, y.x);
        if (ang < 0) ang += double(kTwoPi);
        int sec = int(ang / double(kTwoPi) * sectors);
        if (sec >= sectors) sec = sectors - 1;
        return ring * sectors + sec;
    }

    /// int_cell f(w) dω for every cell (w the unit direction), tensor Gauss–Legendre with n × n
    /// nodes per cell in (|y|, angle).
    std::vector<double> integrals(int n, const std::function<double(const glm::dvec3&)>& f) const {
        GaussLegendre gl(n);
        std::vector<double> out(count());
        const long double jac = std::fabs((long double)l[0][0] * l[1][1] - (long double)l[1][0] * l[0][1]);
        for (int i = 0; i < rings; ++i) {
            const long double r0 = std::sqrt((long double)i / rings), r1 = std::sqrt((long double)(i + 1) / rings);
            for (int j = 0; j < sectors; ++j) {
                const long double a0 = kTwoPi * j / sectors, a1 = kTwoPi * (j + 1) / sectors;
                out[i * sectors + j] = double(gl.integrate([&](long double rho) {
                    return gl.integrate([&](long double ang) {
                        const glm::dvec2 x = q + l * glm::dvec2(double(rho * std::cos(ang)), double(rho * std::sin(ang)));
                        const long double q2 = 1.0L + (long double)x.x * x.x + (long double)x.y * x.y;
                        const glm::dvec3 w = glm::normalize(x.x * e1 + x.y * e2 + z0);
                        return jac * rho / (q2 * std::sqrt(q2)) * (long double)f(w);
                    }, a0, a1);
                }, r0, r1));
            }
        }
        return out;
    }

    std::vector<double> solid_angles(int n) const {
        return integrals(n, [](const glm::dvec3&) { return 1.0; });
    }
};

}  // namespace apse_test
