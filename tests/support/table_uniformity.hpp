// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// How far a tabulation table's density is from uniform: max |pdf Omega − 1| of the tabulated
// radial map over a grid of shapes, shared by test_tabulated (the default table within its
// bound) and accuracy_report (the table-size table of docs/tabulated.md).

#include <apse/comparison.hpp>
#include <apse/spherical_ellipse.hpp>

#include <algorithm>
#include <cmath>

namespace apse_test {

/// The shapes: alpha from 1e-6 rad to the hemisphere, beta/alpha from 1e-3 to 1.
constexpr double table_alphas[] = {1e-6, 1e-3, 0.05, 0.3, 0.7, 1.0, 1.3, 1.45, 1.5, 1.54, 1.555, 1.565, 1.569, 1.5707, 1.5707963};
constexpr double table_ratios[] = {1e-3, 0.01, 0.03, 0.06, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9, 0.99, 1.0};

/// The ellipse of semi-arcs alpha and alpha·ratio about +z.
template <class T> apse::SphericalEllipse<T> ellipse_of_arcs(double alpha, double ratio) {
    using V = glm::vec<3, T>;
    return apse::SphericalEllipse<T>::from_arcs(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), T(alpha), T(alpha * ratio));
}

/// max |pdf Omega − 1| of a map over a 512 x 3 grid of u (u1 over one quadrant: the others are
/// reflections), from sample()'s reported pdf.
template <class T, class Map> double max_uniformity_error(const Map& map, double omega) {
    double worst = 0;
    for (int i = 0; i < 512; ++i)
        for (int j = 0; j < 3; ++j) {
            const auto s = map.sample(glm::vec<2, T>(T((i + 0.5) / 512 * 0.25), T(0.2 + 0.3 * j)));
            worst = std::max(worst, std::fabs(double(s.pdf) * omega - 1));
        }
    return worst;
}

/// max |pdf Omega − 1| of the tabulated map reading `table` over every shape, in double.
template <class Table> double table_uniformity_error(const Table& table) {
    double worst = 0;
    for (double a : table_alphas)
        for (double r : table_ratios) {
            const auto e = ellipse_of_arcs<double>(a, r);
            worst = std::max(worst, max_uniformity_error<double>(apse::TabulatedMap<double>(e, table.view()), e.solid_angle()));
        }
    return worst;
}

}  // namespace apse_test
