// apse demo — the sample points every sampler shares.
// SPDX-License-Identifier: MIT
#pragma once

/// @file points.hpp
/// Per-pixel low-discrepancy points, identical for every sampler: the first two dimensions of
/// the Sobol' sequence (a (0,2)-sequence: every prefix of 2^k points is stratified in all
/// 2^k elementary intervals), Owen-scrambled with a per-pixel seed (a hash-based nested uniform
/// scramble: every binary digit is flipped by a pseudo-random function of the more significant
/// digits). Extra 1-D dimensions (the medium's distance) use a scrambled van der Corput point of
/// a per-pixel shuffled index, which decorrelates them from the light dimensions while keeping
/// every power-of-two prefix stratified.

#include <cstdint>

namespace demo {

/// Bits of x in reverse order.
inline std::uint32_t reverse_bits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

/// A 32-bit integer hash (used for seeds only).
inline std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

/// Nested scramble of the bits of x, read as a binary fraction with the most significant digit
/// in bit 31, i.e. applied to the bit-reversed value: each step changes bit k only as a
/// function of bits < k of the reversed value (addition carries upwards; multiplying by an even
/// constant moves information upwards only), so it permutes every dyadic interval's halves.
inline std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    x = reverse_bits(x);
    x += seed;
    x ^= x * 0x2c1b3c6cu;
    x ^= x * 0x9e3779b8u;
    x += hash32(seed) | 1u;
    x ^= x * 0x5bd1e994u;
    x ^= x * 0xa54ff53au;
    return reverse_bits(x);
}

/// The Sobol' (0,2)-sequence's second coordinate (generator matrix of the primitive
/// polynomial x + 1: v_k = v_{k-1} xor (v_{k-1} >> 1)), as a 32-bit fraction.
inline std::uint32_t sobol_dim1(std::uint32_t i) {
    std::uint32_t r = 0, v = 0x80000000u;
    for (; i; i >>= 1, v ^= v >> 1)
        if (i & 1u) r ^= v;
    return r;
}

inline float to_unit(std::uint32_t bits) {
    return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);  // 24 bits: exactly in [0, 1)
}

/// A 2-D point and a 1-D point for sample `i` of the pixel with seed `pixel_seed`.
struct PixelPoints {
    explicit PixelPoints(std::uint32_t pixel_seed)
        : s0(hash32(pixel_seed * 3u + 0x68e31da4u)), s1(hash32(pixel_seed * 3u + 0xb5297a4du)),
          s2(hash32(pixel_seed * 3u + 0x1b56c4e9u)), s3(hash32(pixel_seed * 5u + 0x2f8e1d3bu)) {}

    /// The light-sampling point: scrambled Sobol' (dimensions 0, 1).
    void light(std::uint32_t i, float& u1, float& u2) const {
        u1 = to_unit(owen_scramble(reverse_bits(i), s0));
        u2 = to_unit(owen_scramble(sobol_dim1(i), s1));
    }

    /// A decorrelated 1-D point (scrambled van der Corput of a shuffled index).
    float extra(std::uint32_t i) const {
        const std::uint32_t j = owen_scramble(i, s3);  // permutes every aligned block of 2^k indices
        return to_unit(owen_scramble(reverse_bits(j), s2));
    }

    std::uint32_t s0, s1, s2, s3;
};

}  // namespace demo
