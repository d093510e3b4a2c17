// apse demo — the multithreaded render loop and its progress bar.
// SPDX-License-Identifier: MIT
#pragma once

/// @file render.hpp
/// render(): every pixel of a scene with one sampler, on all threads (std::thread, rows handed
/// out by an atomic counter), keeping the running mean at several sample counts (progressive
/// snapshots: with the shared Sobol' points, the first 2^k samples are themselves stratified).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "image.hpp"
#include "samplers.hpp"
#include "scene.hpp"

namespace demo {

/// A progress bar on stderr covering a known amount of work (pixel-samples), redrawn at most
/// ~5 times a second and only when stderr is a terminal (otherwise one line per finished step).
class Progress {
public:
    explicit Progress(double total_work);
    void begin(const std::string& label);  ///< a new step (scene × sampler)
    void add(double work);                 ///< thread-safe
    void end();                            ///< finishes the step
    void finish();                         ///< clears the bar

private:
    void draw(bool force);
    struct State;
    std::shared_ptr<State> st_;
};

/// Renders `scene` with sampler `kind`: one image per entry of `marks` (increasing sample
/// counts; the image after marks[k] samples per pixel), with the points seeded by `salt`.
/// Returns the wall time in seconds (negative if `kind` has no sampler for the scene's light).
double render(const Scene& scene, Kind kind, int width, int height, const std::vector<int>& marks, int threads,
              std::uint32_t salt, Progress& progress, std::vector<Image>& out);

/// Scene 1's exact image (closed form, double precision).
Image render_plane_exact(const Scene& scene, int width, int height);

/// Scene 4's reference: the closed form (sphere_radiance_exact) at the ground points where no
/// occluder can block the light (`exact`: 1 there, 0 elsewhere), elsewhere `spp` samples of the
/// tabulated sampler with the points of `salt`.
Image render_sphere_reference(const Scene& scene, int width, int height, int spp, int threads, std::uint32_t salt,
                              Progress& progress, Image& exact);

/// The picture of a render: tonemap() with the scene's tint, scene 4's emitter drawn white.
Canvas display(const Scene& scene, const Image& img, float exposure);

}  // namespace demo
