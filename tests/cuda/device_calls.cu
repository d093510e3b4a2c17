// Compiles every public apse function into a __global__ kernel (nvcc, compile + link only: no
// GPU is needed). Each section calls one header's functions, in the type APSE_DEVICE_CALLS_REAL
// (float or double, one per compilation; see main()); when a header gains a public function, add
// the call here.
#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/math.hpp>
#include <apse/elliptic.hpp>
#include <apse/spherical_rectangle.hpp>
#include <apse/diagnostics.hpp>
#include <apse/comparison.hpp>
#include <apse/runtime_sampler.hpp>

#include <cstdio>

template <class T>
__device__ T elliptic_calls(T a) {
    T s = T(0);
    s += apse::carlson_rf(a, a + T(1), a + T(2));
    s += apse::carlson_rd(a, a + T(1), a + T(2));
    s += apse::carlson_rj(a, a + T(1), a + T(2), a + T(3));
    s += apse::carlson_rc(a, a + T(1));
    s += apse::ellint_f(a, T(0.5));
    s += apse::ellint_pi(T(-2), a, T(0.5));
    s += apse::comp_ellint_k(a);
    s += apse::comp_ellint_pi(T(-2), a);
    return s;
}

template <class T>
__device__ T math_calls(T a) {
    T s = apse::pi_v<T> + apse::half_pi_v<T> + apse::two_pi_v<T>;
    // the scalar helpers of detail/math.hpp that every header shares
    s += apse::detail::safe_sqrt(a) + apse::detail::sqr(a);
    s += apse::detail::clamp(a, T(0), T(1)) + apse::detail::min_of(a, T(1)) + apse::detail::max_of(a, T(0));
    s += apse::quiet_nan<T>() * T(0) + apse::epsilon<T>();
    s += (apse::detail::is_nan(a) || !apse::detail::is_finite(a)) ? T(1) : T(0);
    auto root = apse::detail::find_root_bracketed(
        [a](T x, T& value, T& derivative) { value = x * x - a; derivative = T(2) * x; },
        T(0), T(2), T(1), T(1e-6), 50);
    return s + root.x + T(root.iterations);
}

template <class T>
__device__ T baseline_rectangle_gamito_calls(T a) {
    using V = glm::vec<3, T>;
    using V2 = glm::vec<2, T>;
    const V o(a, T(0.2), T(1)), c(T(0), T(0), T(0)), ex(T(1), T(0), T(0)), ey(T(0), T(1), T(0)), n(T(0), T(0), T(1));
    const V2 u(T(0.3), a);
    const apse::SphericalRectangle<T> r(o, c, ex, ey);
    const auto rc = apse::SphericalRectangle<T>::from_center(o, c, ex, ey);
    const auto rp = r.sample_point(u);
    const auto rl = r.locate(rp.direction);
    T s = r.solid_angle() + rc.solid_angle() + r.sample(u).pdf + rp.distance + rl.st.x + r.pdf(rp.direction);
    s += r.invert(rp.direction).y + (r.empty() ? T(1) : T(0)) + r.corner().x + r.edge_x().x + r.edge_y().y;
    const apse::GamitoSingleShot<T> g1(o, c, n, T(1));
    const apse::GamitoRetry<T> g8(o, c, n, T(1), 8);
    s += g1.sample(u).pdf + g1.sample_point(u).st.x + g1.pdf(rp.direction) + (g1.empty() ? T(1) : T(0));
    s += g1.bounding_rectangle().solid_angle();
    s += g8.sample(u).pdf + g8.sample_point(u).st.y + g8.pdf(rp.direction) + (g8.empty() ? T(1) : T(0));
    s += g8.solid_angle() + g8.acceptance() + g8.success_probability() + T(g8.max_attempts());
    s += g8.bounding_rectangle().solid_angle();
    s += apse::point_on_plane(r.sample(u), o, c, n).distance;
    return s;
}

// Spherical ellipse, projections, area sampling (spherical_ellipse.hpp, projection.hpp,
// baselines/area.hpp, detail/polar.hpp): their own kernel (the ellipse and ellipsoid
// projections inline two 3x3 Jacobi eigen-solvers each).
template <class T>
__global__ void projection_kernel(const T* in, T* out, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    using V = glm::vec<3, T>;
    using E = apse::SphericalEllipse<T>;
    const T a = in[i];
    const V o(a, T(0.2), T(1)), c(T(0)), nrm(T(0), T(0), T(1)), u(T(1), T(0), T(0)), v(T(0), T(0.5), T(0));
    const glm::vec<2, T> uv(a, T(0.6));
    const E d = apse::project_disk(o, c, nrm, T(1));
    const E el = apse::project_ellipse(o, c, u, v);
    const E sp = apse::project_sphere(o, V(T(0), T(0), T(-2)), T(1));
    const E ed = apse::project_ellipsoid(o, V(T(0), T(0), T(-2)), u, v, V(T(0), T(0), T(0.25)));
    const E ft = E::from_tangents(d.x, d.y, d.z, a, T(0.5) * a);
    const E fa = E::from_arcs(d.x, d.y, d.z, a, T(0.5) * a);
    T s = d.solid_angle() + el.solid_angle() + sp.solid_angle() + ed.solid_angle() + ft.solid_angle();
    s += fa.alpha() + E::make_empty().solid_angle() + (d.empty() ? T(1) : T(0)) + (d.contains(o) ? T(1) : T(0));
    s += d.to_local(o).x + d.to_world(o).y + d.m + d.one_minus_m;
    s += (apse::disk_faces(o, c, nrm) ? T(1) : T(0)) + (apse::ellipse_faces(o, c, u, v) ? T(1) : T(0));
    const apse::DiskAreaSampler<T> area(o, c, nrm, T(1));
    const auto smp = area.sample(uv);
    s += smp.pdf + area.pdf(smp.direction) + area.invert(smp.direction).x + area.normal().z + (area.empty() ? T(1) : T(0));
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(c, nrm, T(1));
    const apse::DiskAreaSampler<T> area_f(o, frame);
    s += area_f.sample(uv).pdf + (frame.valid() ? T(1) : T(0)) + apse::project_disk(o, frame).solid_angle();
    const auto pcs = apse::detail::concentric_to_disk_signed(uv);
    s += pcs.radius + pcs.angle;
    const auto pc = apse::detail::concentric_to_disk(uv);
    s += pc.radius + pc.angle() + apse::detail::concentric_from_disk(pc.radius, pc.turns).y;
    out[i] = s;
}

// The maps and disk_light get their own kernel (each sample() inlines an R_J and the inversion
// loop: kept out of the big kernel so that ptxas compiles moderate functions). One call each.
// sample_with_diagnostics reaches the maps' counting sample under nvcc too (sample.hpp's detection)
static_assert(apse::counts_iterations_v<apse::RadialMap<float>> && apse::counts_iterations_v<apse::TabulatedLdRadialMap<double>> &&
                  !apse::counts_iterations_v<apse::DiskAreaSampler<float>>,
              "counts_iterations under nvcc");

template <class T>
__global__ void maps_disk_light_kernel(const T* in, T* out, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    using V = glm::vec<3, T>;
    const T a = in[i];
    const glm::vec<2, T> u(a, T(0.6));
    const auto e = apse::project_disk(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1));
    apse::SampleDiagnostics diag{0};
    T s = T(0);
    if (i % 3 == 0) {
        const apse::RadialMap<T> radial(e);
        const auto d = apse::sample_with_diagnostics(radial, u, diag).direction;
        s += radial.sample(u).pdf + radial.pdf(d) + radial.invert(d).x + radial.solid_angle() + radial.quadrant_area(a) +
             T(radial.empty() ? 1 : 0);
    } else if (i % 3 == 1) {
        const apse::LdRadialMap<T> ld(e);
        const auto d = apse::sample_with_diagnostics(ld, u, diag).direction;
        s += ld.sample(u).pdf + ld.pdf(d) + ld.invert(d).y + ld.solid_angle() + ld.radial().solid_angle() +
             T(ld.empty() ? 1 : 0);
    } else {
        const apse::ParallelMap<T> parallel(e);
        const auto d = apse::sample_with_diagnostics(parallel, u, diag).direction;
        s += parallel.sample(u).pdf + parallel.pdf(d) + parallel.invert(d).x + parallel.solid_angle() + parallel.half_area(a) +
             T(parallel.empty() ? 1 : 0);
    }
    const apse::MapKind m = i % 3 == 0 ? apse::MapKind::radial : (i % 3 == 1 ? apse::MapKind::ld_radial : apse::MapKind::parallel);
    const apse::DiskLight<apse::RuntimeSampler<T>> light(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), m);
    const auto ls = light.sample(u);
    s += ls.pdf + ls.distance + ls.point.x + light.pdf(ls.direction) + light.invert(ls.direction).x + light.solid_angle();
    s += light.ellipse().alpha() + T(light.sampler().kind() == m ? 1 : 0) +
         apse::DiskLight<apse::RuntimeSampler<T>>(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), m).sample(u).pdf;
    s += apse::disk_light_pdf<apse::LdRadialMap<T>>(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), ls.direction);
    // the map's type chosen at compile time
    const apse::DiskLight<apse::LdRadialMap<T>> typed(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1));
    const auto ts = typed.sample(u);
    s += ts.pdf + typed.pdf(ts.direction) + typed.invert(ts.direction).y + typed.solid_angle() + T(typed.empty() ? 1 : 0);
    out[i] = s + T(diag.iterations);
}

// The tabulated maps: a separate small kernel; the table lives in device memory (here: passed
// as a pointer; a real caller copies a host-built TabulationTable there once). Rows are built on
// the device too, to compile the builder.
template <class T>
__global__ void tabulated_kernel(const T* in, T* out, float* table_rows, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    using V = glm::vec<3, T>;
    const T a = in[i];
    if (i == 0) apse::detail::tabulated_fill_row(table_rows, 128, 0.5, 0.25);
    const apse::TabulationView view{table_rows, 128, 17, 9};
    const glm::vec<2, T> u(a, T(0.6));
    const auto e = apse::project_disk(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1));
    T s = T(0);
    if (i % 2 == 0) {
        const apse::TabulatedMap<T> tab(e, view);
        const auto d = tab.sample(u).direction;
        apse::SampleDiagnostics diag{0};
        s += apse::sample_with_diagnostics(tab, u, diag).pdf + T(diag.iterations) + tab.pdf(d) + tab.invert(d).x + T(tab.empty() ? 1 : 0) + tab.ellipse().alpha();
    } else {
        const apse::TabulatedLdRadialMap<T> tld(e, view);
        const auto d = tld.sample(u).direction;
        apse::SampleDiagnostics diag{0};
        s += apse::sample_with_diagnostics(tld, u, diag).pdf + T(diag.iterations) + tld.pdf(d) + tld.invert(d).y + T(tld.empty() ? 1 : 0) + tld.radial().ellipse().beta();
    }
    // DiskLight with the tabulated maps, and the stateless pdf of every sampler (radius as double:
    // it converts to T)
    const apse::MapKind m = i % 2 == 0 ? apse::MapKind::tabulated : apse::MapKind::tabulated_ld_radial;
    const V o(0), c(a, T(0), T(-1)), nrm(0, 0, 1), rn(T(0.2), T(0.1), T(-1));
    const apse::DiskLight<apse::RuntimeSampler<T>> light(o, c, nrm, 1.0, m, view);
    const auto ls = light.sample(u);
    s += ls.pdf + ls.distance + light.pdf(ls.direction) + light.invert(ls.direction).x + light.solid_angle();
    const apse::MapKind k = light.sampler().kind();
    s += T(k == apse::MapKind::tabulated || k == apse::MapKind::tabulated_ld_radial ? 1 : 0) +
         apse::DiskLight<apse::RuntimeSampler<T>>(o, c, nrm, 1, m, view).sample(u).pdf;
    s += apse::disk_light_pdf<apse::RuntimeSampler<T>>(o, c, nrm, 1.0, ls.direction, m, view);
    const apse::DiskLight<apse::RuntimeSampler<T>> framed(o, apse::DiskFrame<T>::make(c, nrm, T(1)), m, view, rn);  // stored frame
    s += framed.sample(u).pdf;
    // the map's type chosen at compile time, from (c, n, r) and from the stored frame; its stateless pdf
    const apse::DiskLight<apse::TabulatedLdRadialMap<T>> typed(o, c, nrm, 1.0, view);
    const auto ts = typed.sample(u);
    s += ts.pdf + typed.pdf(ts.direction) + typed.invert(ts.direction).x + typed.solid_angle() +
         apse::DiskLight<apse::TabulatedLdRadialMap<T>>(o, apse::DiskFrame<T>::make(c, nrm, T(1)), view).sample(u).pdf +
         apse::disk_light_pdf<apse::TabulatedLdRadialMap<T>>(o, c, nrm, 1.0, ts.direction, view);
    out[i] = s;
}

// CosineWeighted over every map, and DiskLight's cosine-weighted option: a kernel of its own.
template <class Map> __device__ typename Map::vec3::value_type cosine_calls(const Map& map, typename Map::vec2 u) {
    using T = typename Map::vec3::value_type;
    const apse::CosineWeighted<Map> c(map, typename Map::vec3(T(0.2), T(0.1), T(-1)));  // facing the light
    const auto d = c.sample(u);
    return d.pdf + c.pdf(d.direction) + c.invert(d.direction).x + T(c.empty() ? 1 : 0) + T(c.weighted() ? 1 : 0) +
           c.ellipse().tan_alpha;
}

template <class T>
__global__ void cosine_kernel(const T* in, T* out, float* table_rows, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    using V = glm::vec<3, T>;
    const T a = in[i];
    const apse::TabulationView view{table_rows, 128, 17, 9};
    const glm::vec<2, T> u(a, T(0.6));
    const auto e = apse::project_disk(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1));
    T s = T(0);
    switch (i % 5) {
    case 0: s += cosine_calls(apse::RadialMap<T>(e), u); break;
    case 1: s += cosine_calls(apse::LdRadialMap<T>(e), u); break;
    case 2: s += cosine_calls(apse::ParallelMap<T>(e), u); break;
    case 3: s += cosine_calls(apse::TabulatedMap<T>(e, view), u); break;
    default: s += cosine_calls(apse::TabulatedLdRadialMap<T>(e, view), u); break;
    }
    const apse::MapKind m = i % 3 == 0 ? apse::MapKind::radial : (i % 3 == 1 ? apse::MapKind::ld_radial : apse::MapKind::parallel);
    const apse::DiskLight<apse::RuntimeSampler<T>> light(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), m, V(T(1), T(0), T(-0.5)));
    const auto ls = light.sample(u);
    s += ls.pdf + light.pdf(ls.direction) + light.invert(ls.direction).x + T(light.cosine_weighted() ? 1 : 0) +
         T(light.sampler().cosine() ? 1 : 0) + T(light.sampler().weighted() ? 1 : 0);
    // cosine-weighted over a tabulated map, and its stateless pdf
    const apse::MapKind mt = i % 2 == 0 ? apse::MapKind::tabulated : apse::MapKind::tabulated_ld_radial;
    const apse::DiskLight<apse::RuntimeSampler<T>> lt(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), mt, view, V(T(1), T(0), T(-0.5)));
    const auto lts = lt.sample(u);
    s += lts.pdf + apse::disk_light_pdf<apse::RuntimeSampler<T>>(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), lts.direction, mt,
                                                                 view, V(T(1), T(0), T(-0.5)));
    s += apse::DiskLight<apse::RuntimeSampler<T>>(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1), mt, view, V(T(1), T(0), T(-0.5)))
             .sample(u)
             .pdf;
    // the cosine-weighted sampler's type chosen at compile time, and its stateless pdf
    const apse::DiskLight<apse::CosineWeighted<apse::LdRadialMap<T>>> typed(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1),
                                                                           V(T(1), T(0), T(-0.5)));
    const auto ts = typed.sample(u);
    s += ts.pdf + typed.pdf(ts.direction) + T(typed.cosine_weighted() ? 1 : 0) +
         apse::disk_light_pdf<apse::CosineWeighted<apse::LdRadialMap<T>>>(V(0), V(a, T(0), T(-1)), V(0, 0, 1), T(1),
                                                                           ts.direction, V(T(1), T(0), T(-0.5)));
    // the projected-solid-angle sampler on its own (and its default, empty state)
    const apse::detail::ProjectedSolidAngleSampler<T> psa(e, V(T(0.2), T(0.1), T(-1)));
    const auto p = psa.sample(u);
    s += p.pdf + psa.pdf(p.direction) + psa.invert(p.direction).y + T(psa.empty() ? 1 : 0) + psa.ellipse().tan_beta +
         apse::detail::ProjectedSolidAngleSampler<T>().pdf(p.direction);
    // the projected-cap sampler on its own (a cap cut by the horizon) and its empty state
    const apse::detail::ProjectedCapSampler<T> pcs(apse::project_sphere(V(0), V(a, T(0), T(3)), T(1)), V(T(1), T(0.1), T(0.2)));
    const auto pc = pcs.sample(u);
    s += pc.pdf + pcs.pdf(pc.direction) + pcs.invert(pc.direction).x + pcs.projected_solid_angle() + T(pcs.cut() ? 1 : 0) +
         apse::detail::ProjectedCapSampler<T>().pdf(pc.direction);
    out[i] = s;
}

// Sphere lights (sphere_light.hpp) over every map, plain and cosine-weighted (the caps' closed
// forms and detail::ProjectedCapSampler), and the stateless pdf: a kernel of its own.
template <class Sampler, class... Args>
__device__ typename Sampler::vec3::value_type sphere_calls(typename Sampler::vec2 u, const Args&... args) {
    using T = typename Sampler::vec3::value_type;
    using V = typename Sampler::vec3;
    const V o(T(0)), c(T(0.5), u.x, T(3));
    const apse::SphereLight<Sampler> light(o, c, T(1), args...);
    const auto s = light.sample(u);
    return s.pdf + s.distance + s.point.x + light.pdf(s.direction) + light.invert(s.direction).x +
           light.solid_angle() + T(light.empty() ? 1 : 0) + light.ellipse().tan_alpha +
           T(light.ellipse().is_cap() ? 1 : 0) + apse::sphere_light_pdf<Sampler>(o, c, T(1), s.direction, args...);
}

template <class T>
__global__ void sphere_kernel(const T* in, T* out, float* table_rows, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    using V = glm::vec<3, T>;
    const apse::TabulationView view{table_rows, 128, 17, 9};
    const glm::vec<2, T> u(in[i], T(0.6));
    const V rn(T(1), T(0), T(0.2));  // the receiver normal: the cap straddles its horizon
    T s = T(0);
    switch (i % 12) {
    case 0: s += sphere_calls<apse::RadialMap<T>>(u); break;
    case 1: s += sphere_calls<apse::LdRadialMap<T>>(u); break;
    case 2: s += sphere_calls<apse::ParallelMap<T>>(u); break;
    case 3: s += sphere_calls<apse::TabulatedMap<T>>(u, view); break;
    case 4: s += sphere_calls<apse::TabulatedLdRadialMap<T>>(u, view); break;
    case 5: s += sphere_calls<apse::CosineWeighted<apse::RadialMap<T>>>(u, rn); break;
    case 6: s += sphere_calls<apse::CosineWeighted<apse::LdRadialMap<T>>>(u, rn); break;
    case 7: s += sphere_calls<apse::CosineWeighted<apse::ParallelMap<T>>>(u, rn); break;
    case 8: s += sphere_calls<apse::CosineWeighted<apse::TabulatedMap<T>>>(u, view, rn); break;
    case 9: s += sphere_calls<apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>>(u, view, rn); break;
    // the map chosen at run time (the choice among the cap samplers), plain and cosine-weighted
    case 10: s += sphere_calls<apse::RuntimeSampler<T>>(u, apse::MapKind(i % 5), view); break;
    default: s += sphere_calls<apse::RuntimeSampler<T>>(u, apse::MapKind(i % 5), view, rn); break;
    }
    // the projected-cap sampler on its own
    const apse::detail::ProjectedCapSampler<T> cap(apse::project_sphere(V(0), V(T(0.5), u.x, T(3)), T(1)), rn);
    const auto p = cap.sample(u);
    s += p.pdf + cap.pdf(p.direction) + cap.invert(p.direction).y + T(cap.empty() ? 1 : 0) + cap.projected_solid_angle();
    out[i] = s;
}

template <class T>
__global__ void all_public_functions(const T* in, T* out, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    const T a = in[i];
    out[i] = baseline_rectangle_gamito_calls(a) + math_calls(a) + elliptic_calls(a);
}

// The kernels of one type per compilation (float or double: the test suite compiles both, in
// parallel, as cuda_device_compile_float and cuda_device_compile_double).
#ifndef APSE_DEVICE_CALLS_REAL
#define APSE_DEVICE_CALLS_REAL float
#endif
using Real = APSE_DEVICE_CALLS_REAL;

int main() {
    // Taking the kernels' addresses forces their instantiation and device compilation.
    void (*k)(const Real*, Real*, int) = all_public_functions<Real>;
    void (*m)(const Real*, Real*, int) = maps_disk_light_kernel<Real>;
    void (*p)(const Real*, Real*, int) = projection_kernel<Real>;
    void (*t)(const Real*, Real*, float*, int) = tabulated_kernel<Real>;
    void (*c)(const Real*, Real*, float*, int) = cosine_kernel<Real>;
    void (*s)(const Real*, Real*, float*, int) = sphere_kernel<Real>;
    std::printf("device kernels compiled (%s): %p %p %p %p %p %p\n", sizeof(Real) == 4 ? "float" : "double",
                reinterpret_cast<void*>(k), reinterpret_cast<void*>(m), reinterpret_cast<void*>(p),
                reinterpret_cast<void*>(t), reinterpret_cast<void*>(c), reinterpret_cast<void*>(s));
    return 0;
}
