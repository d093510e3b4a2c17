// GPU throughput of apse's samplers: per shading point, the set-up plus 1 sample, and the set-up
// plus 16 samples, for each sampler in float and double, against the lean area sampler
// (DiskAreaSampler from the light's stored DiskFrame) measured in the same run. 2^24 shading
// points per launch (one thread each), over the seeded configurations of the CPU benchmarks
// (bench/support/disk_configs.hpp: 1024 disks, 0.1–1000 radii away, and sphere_configs.hpp),
// uploaded once; each thread reads configuration i mod 1024 and points of the square from the
// shared 4096. Timed with CUDA events: the median of 7 launches after one warm-up launch.
// Also reported per kernel: registers per thread, local memory (stack and spills) per thread,
// and the theoretical occupancy at 128 threads per block (cudaOccupancyMaxActiveBlocksPerMultiprocessor).
// Prints a markdown table; exit code 77 (skipped) without a CUDA device. Options: -n LOG2 (shading
// points per launch, default 24), -r REPS (timed launches, default 7). Built with
// -DAPSE_BENCH_GROUP=g (0 to 2) it measures one group of samplers (and the reference).
#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/comparison.hpp>
#include <apse/runtime_sampler.hpp>

#include "../support/disk_configs.hpp"
#include "../support/sphere_configs.hpp"

#include <cuda_runtime.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace apse_gpu_bench {

template <class T> using V2 = glm::vec<2, T>;
template <class T> using V3 = glm::vec<3, T>;
template <class T> using Disk = apse_bench::DiskConfig<T>;
template <class T> using Sphere = apse_bench::SphereConfig<T>;

/// What a kernel reads: the configurations, the points of the square and the table.
template <class T> struct Inputs {
    const Disk<T>* disks;
    const Sphere<T>* spheres;
    const V2<T>* u;
    apse::TabulationView table;
};

// The samplers: `make` builds one for shading point i (the per-point set-up).
#define APSE_BENCH_KIND(Kind, Label, Expr)                                                            \
    struct Kind {                                                                                     \
        static constexpr const char* name = Label;                                                    \
        template <class T> static __device__ auto make(const Inputs<T>& in, int i) {                  \
            const Disk<T>& d = in.disks[i & (apse_bench::DiskConfigs<T>::disk_count - 1)];            \
            const Sphere<T>& s = in.spheres[i & (apse_bench::SphereConfigs<T>::count - 1)];    \
            (void)d;                                                                                  \
            (void)s;                                                                                  \
            return Expr;                                                                              \
        }                                                                                             \
    };

APSE_BENCH_KIND(BArea, "DiskAreaSampler (stored DiskFrame)", apse::DiskAreaSampler<T>(d.o, d.frame))
APSE_BENCH_KIND(BRadial, "RadialMap", apse::RadialMap<T>(apse::project_disk(d.o, d.frame)))
APSE_BENCH_KIND(BLdRadial, "LdRadialMap", apse::LdRadialMap<T>(apse::project_disk(d.o, d.frame)))
APSE_BENCH_KIND(BParallel, "ParallelMap", apse::ParallelMap<T>(apse::project_disk(d.o, d.frame)))
APSE_BENCH_KIND(BTabulated, "TabulatedMap", apse::TabulatedMap<T>(apse::project_disk(d.o, d.frame), in.table))
APSE_BENCH_KIND(BTabulatedLd, "TabulatedLdRadialMap", apse::TabulatedLdRadialMap<T>(apse::project_disk(d.o, d.frame), in.table))
APSE_BENCH_KIND(BCosLd, "CosineWeighted<LdRadialMap>",
                apse::CosineWeighted<apse::LdRadialMap<T>>(apse::project_disk(d.o, d.frame), d.half_y))
APSE_BENCH_KIND(BCosTabulatedLd, "CosineWeighted<TabulatedLdRadialMap>",
                apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>(apse::project_disk(d.o, d.frame), in.table, d.half_y))
APSE_BENCH_KIND(BDiskLight, "DiskLight<RuntimeSampler> (ld_radial, stored DiskFrame)",
                apse::DiskLight<apse::RuntimeSampler<T>>(d.o, d.frame, apse::MapKind::ld_radial))
APSE_BENCH_KIND(BDiskLightTab, "DiskLight<RuntimeSampler> (tabulated_ld_radial)",
                apse::DiskLight<apse::RuntimeSampler<T>>(d.o, d.frame, apse::MapKind::tabulated_ld_radial, in.table))
APSE_BENCH_KIND(BGamitoRetry, "GamitoRetry(8)", apse::GamitoRetry<T>(d.o, d.c, d.n, d.r, 8))
APSE_BENCH_KIND(BSphereLd, "SphereLight<LdRadialMap>", apse::SphereLight<apse::LdRadialMap<T>>(s.o, s.c, s.r))
APSE_BENCH_KIND(BSphereCosLd, "SphereLight<CosineWeighted<LdRadialMap>> (mixed)",
                apse::SphereLight<apse::CosineWeighted<apse::LdRadialMap<T>>>(s.o, s.c, s.r, s.mixed))
#undef APSE_BENCH_KIND

template <class... K> struct KindList {};
#if !defined(APSE_BENCH_GROUP)
using Kinds = KindList<BArea, BRadial, BLdRadial, BParallel, BTabulated, BTabulatedLd, BCosLd, BCosTabulatedLd, BDiskLight,
                       BDiskLightTab, BGamitoRetry, BSphereLd, BSphereCosLd>;
#elif APSE_BENCH_GROUP == 0
using Kinds = KindList<BArea, BRadial, BLdRadial, BParallel, BGamitoRetry>;
#elif APSE_BENCH_GROUP == 1
using Kinds = KindList<BArea, BTabulated, BTabulatedLd, BDiskLight, BDiskLightTab>;
#elif APSE_BENCH_GROUP == 2
using Kinds = KindList<BArea, BCosLd, BCosTabulatedLd, BSphereLd, BSphereCosLd>;
#else
#error "APSE_BENCH_GROUP must be 0 to 2"
#endif

/// One thread per shading point: the set-up, then S samples; the sum of the results is written
/// so that nothing is optimised away. No __launch_bounds__: ptxas allots registers as it does for
/// a renderer's kernel written plainly (with __launch_bounds__(128) it capped most of them at 128
/// or 168 registers and spilled up to ~0.8 KB per thread).
template <class Kind, int S, class T>
__global__ void throughput_kernel(Inputs<T> in, T* out, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    const auto sampler = Kind::template make<T>(in, i);
    T acc = T(0);
#pragma unroll 1
    for (int s = 0; s < S; ++s) {
        const V2<T> u = in.u[(i * S + s) & (apse_bench::DiskConfigs<T>::u_count - 1)];
        const auto smp = sampler.sample(u);
        acc += smp.direction.x + smp.direction.y + smp.direction.z + (smp.pdf > T(0) ? T(1) : T(0));
    }
    out[i] = acc;
}

bool check(cudaError_t e, const char* what) {
    if (e == cudaSuccess) return true;
    std::printf("CUDA error in %s: %s\n", what, cudaGetErrorString(e));
    return false;
}

template <class T> T* upload(const std::vector<T>& v) {
    T* d = nullptr;
    if (!check(cudaMalloc(&d, v.size() * sizeof(T)), "cudaMalloc")) return nullptr;
    if (!check(cudaMemcpy(d, v.data(), v.size() * sizeof(T), cudaMemcpyHostToDevice), "cudaMemcpy")) return nullptr;
    return d;
}

struct Options {
    int log2_points = 24;
    int reps = 7;
};

struct Row {
    double samples_per_s = 0;  // 0: failed
    int regs = 0;
    int local_bytes = 0;
    double occupancy = 0;
};

/// Median time of `reps` launches (after one warm-up) of the kernel for Kind, S, T.
template <class Kind, int S, class T> Row measure(const Inputs<T>& in, T* out, const Options& opt, const cudaDeviceProp& prop) {
    Row row;
    auto kernel = throughput_kernel<Kind, S, T>;
    cudaFuncAttributes attr{};
    if (!check(cudaFuncGetAttributes(&attr, kernel), "cudaFuncGetAttributes")) return row;
    row.regs = attr.numRegs;
    row.local_bytes = int(attr.localSizeBytes);
    const int block = 128;
    int blocks_per_sm = 0;
    if (check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&blocks_per_sm, kernel, block, 0), "occupancy"))
        row.occupancy = double(blocks_per_sm * block) / prop.maxThreadsPerMultiProcessor;
    const int n = 1 << opt.log2_points;
    const int grid = (n + block - 1) / block;
    cudaEvent_t start, stop;
    cudaEventCreate(&start);
    cudaEventCreate(&stop);
    std::vector<float> ms;
    bool ok = true;
    for (int r = 0; r <= opt.reps && ok; ++r) {
        cudaEventRecord(start);
        kernel<<<grid, block>>>(in, out, n);
        cudaEventRecord(stop);
        ok = check(cudaGetLastError(), Kind::name) && check(cudaEventSynchronize(stop), Kind::name);
        float t = 0;
        cudaEventElapsedTime(&t, start, stop);
        if (r > 0) ms.push_back(t);  // r == 0: warm-up
    }
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
    if (!ok || ms.empty()) return row;
    std::sort(ms.begin(), ms.end());
    const double median_s = 1e-3 * ms[ms.size() / 2];
    row.samples_per_s = median_s > 0 ? double(n) * S / median_s : 0;
    return row;
}

template <class T, class... K> int run_type(KindList<K...>, const Options& opt, const cudaDeviceProp& prop,
                                             const apse::TabulationView& table) {
    const char* tname = sizeof(T) == 4 ? "float" : "double";
    const auto& dc = apse_bench::disk_configs<T>();
    const auto& sc = apse_bench::sphere_configs<T>();
    Inputs<T> in{upload(dc.disks), upload(sc.spheres), upload(dc.u), table};
    T* out = nullptr;
    if (!in.disks || !in.spheres || !in.u || !check(cudaMalloc(&out, (std::size_t(1) << opt.log2_points) * sizeof(T)), "cudaMalloc"))
        return 1;
    int failures = 0;
    Row area1, area16;
    auto one = [&](auto tag) {
        using Kind = decltype(tag);
        const Row r1 = measure<Kind, 1, T>(in, out, opt, prop);
        const Row r16 = measure<Kind, 16, T>(in, out, opt, prop);
        if (std::is_same<Kind, BArea>::value) {
            area1 = r1;
            area16 = r16;
        }
        if (!(r1.samples_per_s > 0) || !(r16.samples_per_s > 0)) ++failures;
        auto ratio = [](const Row& r, const Row& a) { return a.samples_per_s > 0 ? r.samples_per_s / a.samples_per_s : 0.0; };
        std::printf("| %-50s | %-6s | %9.3g | %5.2f | %9.3g | %5.2f | %3d/%-3d | %4d/%-4d | %3.0f%%/%3.0f%% |\n", Kind::name, tname,
                    r1.samples_per_s, ratio(r1, area1), r16.samples_per_s, ratio(r16, area16), r1.regs, r16.regs,
                    r1.local_bytes, r16.local_bytes, 100 * r1.occupancy, 100 * r16.occupancy);
    };
    (one(K{}), ...);  // BArea first: the reference of every later row
    cudaFree(out);
    cudaFree(const_cast<Disk<T>*>(in.disks));
    cudaFree(const_cast<Sphere<T>*>(in.spheres));
    cudaFree(const_cast<V2<T>*>(in.u));
    return failures;
}

}  // namespace apse_gpu_bench

int main(int argc, char** argv) {
    using namespace apse_gpu_bench;
    Options opt;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "-n")) opt.log2_points = std::max(10, std::min(26, std::atoi(argv[i + 1])));
        if (!std::strcmp(argv[i], "-r")) opt.reps = std::max(1, std::min(50, std::atoi(argv[i + 1])));
    }
    int count = 0;
    const cudaError_t e = cudaGetDeviceCount(&count);
    if (e != cudaSuccess || count == 0) {
        std::printf("skipped: no CUDA device (%s)\n", e != cudaSuccess ? cudaGetErrorString(e) : "none found");
        return 77;
    }
    cudaDeviceProp prop{};
    cudaGetDeviceProperties(&prop, 0);
    if (!check(cudaDeviceSetLimit(cudaLimitStackSize, 16384), "cudaDeviceSetLimit")) return 1;
    const apse::TabulationTable& host_table = apse::default_table();
    apse::TabulationTable* device_table = nullptr;
    if (!check(cudaMalloc(&device_table, sizeof(apse::TabulationTable)), "cudaMalloc") ||
        !check(cudaMemcpy(device_table, &host_table, sizeof(apse::TabulationTable), cudaMemcpyHostToDevice), "cudaMemcpy"))
        return 1;
    const apse::TabulationView table{device_table->cdf, apse::TabulationTable::bins, apse::TabulationTable::alpha_nodes,
                                     apse::TabulationTable::ratio_nodes};
    std::printf("apse GPU throughput on %s (sm_%d%d, %d SMs): 2^%d shading points per launch, median of %d launches\n",
                prop.name, prop.major, prop.minor, prop.multiProcessorCount, opt.log2_points, opt.reps);
    std::printf("samples/s: set-up + 1 sample (x1) and set-up + 16 samples (x16) per shading point; ratio: to the area\n"
                "sampler's samples/s in the same run; regs, local bytes (stack + spills) per thread and theoretical\n"
                "occupancy at 128 threads per block, for the x1/x16 kernels.\n\n");
    std::printf("| %-50s | %-6s | %9s | %5s | %9s | %5s | %7s | %9s | %9s |\n", "sampler", "T", "x1 /s", "ratio", "x16 /s",
                "ratio", "regs", "local B", "occupancy");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    int failures = run_type<float>(Kinds{}, opt, prop, table);
    failures += run_type<double>(Kinds{}, opt, prop, table);
    cudaFree(device_table);
    std::printf("\n%s\n", failures == 0 ? "all kernels ran" : "some kernels failed (see above)");
    return failures == 0 ? 0 : 1;
}
