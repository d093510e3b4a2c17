// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/tabulation_table.hpp
/// The table the tabulated maps (maps/tabulated_ld_radial.hpp) draw from: `TabulationTableN` /
/// `TabulationTable` (its rows: the normalised CDF of the closed-form area density in the
/// Lambert anomaly, for a grid of ellipse shapes, docs/math.md §6), its non-owning
/// `TabulationView`, and `default_table()`.
///
/// Why a user-built table object (design choice): the table's entries are integrals of the
/// closed-form density above, so apse builds them itself (`TabulationTable::build()`, ~15 ms,
/// Gauss–Legendre per bin, no elliptic integrals) instead of shipping a generated array; the
/// object is plain data (trivially copyable, no pointers), so a GPU user copies it once to device
/// memory and passes a `TabulationView` pointing there (namespace-scope constexpr arrays would
/// need a separate `__constant__` copy for device code). Entries are stored as float for both
/// T = float and double: any monotone table gives an exact sampler, and float entries are ~1e-7
/// from the exact CDF, far below the tabulation error. Default size: 128 bins × 17 alpha nodes ×
/// 9 ratio nodes = 19 737 floats = 77 KB.

#include <cmath>

#include "../config.hpp"
#include "../detail/math.hpp"

namespace apse {

/// A non-owning view of a tabulation table (see TabulationTableN): `cdf` points at
/// `alpha_nodes * ratio_nodes` rows of `bins + 1` floats each, row (i, j) (alpha node i, ratio
/// node j) at offset (i * ratio_nodes + j) * (bins + 1); each row is a CDF (0 first, 1 last,
/// increasing). In device code `cdf` must point to device memory. A view with a null pointer or
/// fewer than 1 bin / 2 nodes makes every map built from it empty (pdf 0).
struct TabulationView {
    const float* cdf;  ///< rows of normalised cumulative quadrant area in lambda
    int bins;          ///< N: bins per row (equal width pi/(2N) in lambda)
    int alpha_nodes;   ///< nodes of x = 1 − sqrt(cos alpha) in [0, 1] (equally spaced)
    int ratio_nodes;   ///< nodes of y = beta/alpha in [0, 1] (equally spaced)
};

namespace detail {

/// Whether `table` can serve a tabulated map: rows present, at least one bin and two nodes per
/// axis (a tabulated map, or its cap sampler, built with any other view is empty).
APSE_FUNC bool table_usable(const TabulationView& table) noexcept {
    return table.cdf != nullptr && table.bins >= 1 && table.alpha_nodes >= 2 && table.ratio_nodes >= 2;
}

/// Unnormalised area density of the quadrant in the Lambert anomaly lambda (maps/tabulated_ld_radial.hpp
/// file comment), divided by the constant a b: kappa / ((1 + C(tau)) (cos^2 lambda + kappa^2
/// sin^2 lambda)), for cos alpha = ca, cos beta = cb, kappa = sqrt((1 + ca)/(1 + cb)), lambda in
/// [0, pi/2]. Double precision (table construction only).
APSE_FUNC double tabulated_lambda_density(double lambda, double ca, double cb, double kappa) noexcept {
    const double cl = std::cos(lambda), sl = std::sin(lambda);
    const double n2 = cl * cl + kappa * kappa * sl * sl;
    const double ct2 = cl * cl / n2, st2 = kappa * kappa * sl * sl / n2;
    const double c = std::sqrt(ca * ca * ct2 + cb * cb * st2);
    return kappa / ((1.0 + c) * n2);
}

/// Fills one row (bins + 1 floats) of the tabulation table for the shape (alpha, beta): the
/// normalised cumulative integral of tabulated_lambda_density at lambda_k = k pi/(2 bins),
/// 5-point Gauss–Legendre per bin (the float entries agree with a 64 times finer quadrature to
/// within one float rounding, 6e-8, for shapes up to the hemisphere).
APSE_FUNC void tabulated_fill_row(float* row, int bins, double alpha, double beta) noexcept {
    const double ca = std::cos(alpha), cb = std::cos(beta);
    const double kappa = std::sqrt((1.0 + ca) / (1.0 + cb));
    const double x[5] = {0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640, -0.9061798459386640};
    const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                         0.2369268850561891};
    const double h = 1.5707963267948966 / bins;
    double total = 0.0;
    // first pass: the total; second pass: the normalised running sum (deterministic, no storage)
    for (int pass = 0; pass < 2; ++pass) {
        double sum = 0.0;
        if (pass == 1) row[0] = 0.0f;
        for (int k = 0; k < bins; ++k) {
            const double mid = (k + 0.5) * h;
            double s = 0.0;
            for (int g = 0; g < 5; ++g) s += w[g] * tabulated_lambda_density(mid + 0.5 * h * x[g], ca, cb, kappa);
            sum += 0.5 * h * s;
            if (pass == 1) row[k + 1] = k + 1 == bins ? 1.0f : float(sum / total);
        }
        total = sum;
    }
}

}  // namespace detail

/// The tabulation table shared by all TabulatedMap / TabulatedLdRadialMap instances (docs/math.md §6,
/// redone unbiased; maps/tabulated_ld_radial.hpp file comment): Bins + 1 CDF entries in lambda for each of
/// AlphaNodes × RatioNodes shapes: sqrt(cos alpha) = 1 − i/(AlphaNodes − 1) (nodes dense near the
/// hemisphere, where the density changes fastest with the shape), beta = alpha j/(RatioNodes − 1).
/// Plain data, trivially copyable (copy it to device memory as is); memory
/// AlphaNodes × RatioNodes × (Bins + 1) × 4 bytes. Build it once with build() before use.
template <int Bins, int AlphaNodes, int RatioNodes> struct TabulationTableN {
    static_assert(Bins >= 1 && AlphaNodes >= 2 && RatioNodes >= 2, "apse: table too small");
    static constexpr int bins = Bins;                ///< N
    static constexpr int alpha_nodes = AlphaNodes;   ///< nodes of 1 − sqrt(cos alpha)
    static constexpr int ratio_nodes = RatioNodes;   ///< nodes of beta/alpha
    static constexpr int size = AlphaNodes * RatioNodes * (Bins + 1);  ///< number of floats

    float cdf[size];  ///< the rows, layout as TabulationView

    /// Computes every row (double-precision quadrature of the closed-form density; no elliptic
    /// integrals). Cost ~ size × 10 evaluations (~15 ms for the default size). Host or device.
    /// Deterministic and idempotent: a second call rewrites the same values. Not safe while
    /// another thread reads or builds the same table (a data race): build it before sharing it,
    /// or use default_table(), which builds the default table once, thread-safely.
    APSE_FUNC void build() noexcept {
        for (int i = 0; i < AlphaNodes; ++i) {
            const double x = double(i) / double(AlphaNodes - 1), sc = 1.0 - x;  // sqrt(cos alpha)
            const double alpha = i == AlphaNodes - 1 ? 1.5707963267948966 : std::acos(sc * sc);
            for (int j = 0; j < RatioNodes; ++j) {
                const double beta = alpha * double(j) / double(RatioNodes - 1);
                detail::tabulated_fill_row(cdf + (i * RatioNodes + j) * (Bins + 1), Bins, alpha, beta);
            }
        }
    }

    /// A view of this table (valid while the table lives; for device use make a view of the
    /// device copy instead: `TabulationView{device_ptr->cdf, bins, alpha_nodes, ratio_nodes}`).
    APSE_FUNC TabulationView view() const noexcept { return {cdf, Bins, AlphaNodes, RatioNodes}; }
};

/// The default table: 128 bins × 17 × 9 shapes = 19 737 floats = 77 KB; max |pdf Omega − 1| =
/// 0.44 % over all shapes (docs/tabulated.md; the error is ~0.56/N, set by the bins).
using TabulationTable = TabulationTableN<128, 17, 9>;

/// The default TabulationTable, built on the first call and shared by every later one: a
/// reference to a function-local static (77 KB, static storage), so it lives until the program
/// exits. Thread-safe: C++ runs a function-local static's initialisation exactly once, and
/// threads calling it meanwhile wait for it (scenes loaded on worker threads may all call it);
/// the first call takes ~15 ms, later ones a guard check. Host only (not APSE_FUNC): device code
/// reads a copy in device memory through a TabulationView (`default_table()` copied once, e.g.
/// with cudaMemcpy). One table per program (an inline function: every translation unit shares
/// it; a shared library that does not export its symbols may hold its own copy).
inline const TabulationTable& default_table() noexcept {
    struct Built {
        TabulationTable table;
        Built() noexcept { table.build(); }
    };
    static const Built built;
    return built.table;
}

}  // namespace apse
