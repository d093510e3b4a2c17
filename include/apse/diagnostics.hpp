// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file diagnostics.hpp
/// What one sample cost, for tests and benchmarks (`sample_with_diagnostics`): the iterations of
/// a map's numerical inversion or table walk. Not included by apse.hpp; the samplers' own
/// `sample(u)` carries no diagnostics, so the rendering path pays nothing for them.

#include <type_traits>
#include <utility>

#include "config.hpp"
#include "sample.hpp"
#include "detail/glm.hpp"

namespace apse {

/// What apse::sample_with_diagnostics reports about one sample.
struct SampleDiagnostics {
    /// Iterative steps the sample took: Newton/Halley iterations of the cumulative-area inversion
    /// (RadialMap, LdRadialMap, ParallelMap; 0 when the first guess was already exact) or
    /// table-walk steps (TabulatedMap, TabulatedLdRadialMap; 0 when the uniform guess was the
    /// bin). 0 for the samplers that do not count (`counts_iterations<S>` is false).
    int iterations;
};

namespace detail {

/// True if S has a counting implementation: a member `sample_counted(u, int& iterations)` (the
/// maps; their `sample(u)` calls the same implementation, the count optimised away).
template <class S, class = void> struct has_sample_counted : std::false_type {};
template <class S>
struct has_sample_counted<S, std::void_t<decltype(std::declval<const S&>().sample_counted(
                                 std::declval<const typename S::vec2&>(), std::declval<int&>()))>> : std::true_type {};

}  // namespace detail

/// True if the sampler type S reports its iterations through sample_with_diagnostics: the five
/// maps. False for the closed-form samplers (DiskAreaSampler) and those that do not count
/// (SphericalRectangle, the Gamito samplers, CosineWeighted, DiskLight): their
/// SampleDiagnostics::iterations is always 0.
template <class S> struct counts_iterations : detail::has_sample_counted<S> {};

/// counts_iterations<S>::value.
template <class S> constexpr bool counts_iterations_v = counts_iterations<S>::value;

/// `sampler.sample(u)` — the same result, bit for bit — with what the sample cost written to
/// `diagnostics` (SampleDiagnostics: iterations; 0 for samplers that do not count, see
/// counts_iterations). Works for every apse sampler; for benchmarks and tests (the samplers'
/// own `sample(u)` carries no diagnostics, so the rendering path pays nothing for them).
template <class Sampler, class T>
APSE_HOT_INLINE auto sample_with_diagnostics(const Sampler& sampler, const glm::vec<2, T>& u,
                                       SampleDiagnostics& diagnostics) noexcept {
    diagnostics.iterations = 0;
    if constexpr (counts_iterations<Sampler>::value)
        return sampler.sample_counted(u, diagnostics.iterations);
    else
        return sampler.sample(u);
}

}  // namespace apse
