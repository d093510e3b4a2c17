// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/type_identity.hpp
/// `type_identity_t<T>` (C++20's std::type_identity_t, for C++17): a scalar parameter written
/// `type_identity_t<T> radius` takes no part in deducing T, so T comes from the vector arguments
/// alone and the scalar converts to it — `project_disk(vec3, vec3, vec3, 1.0)` (float vectors,
/// a double or int radius) is a float call instead of a deduction failure.

namespace apse {
namespace detail {

/// Holds T unchanged (a non-deduced context).
template <class T> struct type_identity {
    using type = T;  ///< T itself
};

/// T, in a non-deduced context.
template <class T> using type_identity_t = typename type_identity<T>::type;

}  // namespace detail
}  // namespace apse
