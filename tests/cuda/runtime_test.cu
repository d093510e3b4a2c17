// Runs every apse sampler on the GPU and compares the results with the host's (the cases, the
// evaluation and the comparison: runtime_cases.hpp, whose file comment states the bounds and
// why). One kernel per sampler and scalar type; the tabulated maps read a device copy of
// apse::default_table() through a TabulationView. Prints one line per sampler (the largest
// differences found) and ends with "N passed, N failed"; exit code 0 if all passed, 1 if not,
// 77 (skipped) when no CUDA device is present. Built with -DAPSE_RT_GROUP=g (0 to 7) it runs one
// group of samplers only (tools/gpu_check.sh compiles the groups in parallel).
#include "runtime_cases.hpp"

#include <cuda_runtime.h>

#include <cstdio>
#include <vector>

namespace {

template <class Kind, class T>
__global__ void evaluate_kernel(const apse_rt::Config<T>* configs, const apse_rt::Case<T>* cases, apse_rt::Output<T>* out,
                                int n, apse::TabulationView view) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    const apse_rt::Case<T> k = cases[i];
    out[i] = Kind::template run<T>(configs[k.config], k, view);
}

bool check(cudaError_t e, const char* what) {
    if (e == cudaSuccess) return true;
    std::printf("CUDA error in %s: %s\n", what, cudaGetErrorString(e));
    return false;
}

/// The device side: copies configurations and cases to the device, runs the kind's kernel,
/// copies the outputs back (an empty vector on any CUDA error).
struct CudaDevice {
    apse::TabulationView table;  // a view of the device copy of the table

    template <class Kind, class T>
    std::vector<apse_rt::Output<T>> run(const std::vector<apse_rt::Config<T>>& configs,
                                        const std::vector<apse_rt::Case<T>>& cases) const {
        std::vector<apse_rt::Output<T>> out(cases.size());
        apse_rt::Config<T>* dc = nullptr;
        apse_rt::Case<T>* dk = nullptr;
        apse_rt::Output<T>* dout = nullptr;
        const int n = int(cases.size());
        bool ok = check(cudaMalloc(&dc, configs.size() * sizeof(configs[0])), "cudaMalloc") &&
                  check(cudaMalloc(&dk, cases.size() * sizeof(cases[0])), "cudaMalloc") &&
                  check(cudaMalloc(&dout, out.size() * sizeof(out[0])), "cudaMalloc") &&
                  check(cudaMemcpy(dc, configs.data(), configs.size() * sizeof(configs[0]), cudaMemcpyHostToDevice), "cudaMemcpy") &&
                  check(cudaMemcpy(dk, cases.data(), cases.size() * sizeof(cases[0]), cudaMemcpyHostToDevice), "cudaMemcpy");
        if (ok) {
            const int block = 128;
            evaluate_kernel<Kind, T><<<(n + block - 1) / block, block>>>(dc, dk, dout, n, table);
            ok = check(cudaGetLastError(), Kind::name) && check(cudaDeviceSynchronize(), Kind::name) &&
                 check(cudaMemcpy(out.data(), dout, out.size() * sizeof(out[0]), cudaMemcpyDeviceToHost), "cudaMemcpy");
        }
        cudaFree(dc);
        cudaFree(dk);
        cudaFree(dout);
        if (!ok) out.clear();
        return out;
    }
};

}  // namespace

int main() {
    int count = 0;
    const cudaError_t e = cudaGetDeviceCount(&count);
    if (e != cudaSuccess || count == 0) {
        std::printf("skipped: no CUDA device (%s)\n", e != cudaSuccess ? cudaGetErrorString(e) : "none found");
        return 77;
    }
    cudaDeviceProp prop{};
    cudaGetDeviceProperties(&prop, 0);
#if defined(APSE_RT_GROUP)
    std::printf("apse runtime test, group %d of %d, on %s (sm_%d%d)\n\n", APSE_RT_GROUP, apse_rt::kGroups, prop.name,
                prop.major, prop.minor);
#else
    std::printf("apse runtime test on %s (sm_%d%d)\n\n", prop.name, prop.major, prop.minor);
#endif
    // The samplers keep their state in registers and local memory; each thread's frame is the
    // kernel's (ptxas -v reports it): raise the stack limit so that no launch is refused for it.
    if (!check(cudaDeviceSetLimit(cudaLimitStackSize, 16384), "cudaDeviceSetLimit")) return 1;

    // the tabulation table: the host's, and a device copy read through a view
    const apse::TabulationTable& host_table = apse::default_table();
    apse::TabulationTable* device_table = nullptr;
    if (!check(cudaMalloc(&device_table, sizeof(apse::TabulationTable)), "cudaMalloc") ||
        !check(cudaMemcpy(device_table, &host_table, sizeof(apse::TabulationTable), cudaMemcpyHostToDevice), "cudaMemcpy"))
        return 1;
    const CudaDevice device{apse::TabulationView{device_table->cdf, apse::TabulationTable::bins,
                                                 apse::TabulationTable::alpha_nodes, apse::TabulationTable::ratio_nodes}};

    int passed = 0, failed = 0;
    apse_rt::print_header();
    apse_rt::run_all<float>(device, apse_rt::Kinds{}, host_table.view(), passed, failed);
    apse_rt::run_all<double>(device, apse_rt::Kinds{}, host_table.view(), passed, failed);
    cudaFree(device_table);
    std::printf("\n%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
