// apse demo — the multithreaded render loop and its progress bar.
// SPDX-License-Identifier: MIT
#include "render.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>

namespace demo {

using Clock = std::chrono::steady_clock;

struct Progress::State {
    double total = 1, done = 0;
    std::string label;
    bool tty = false;
    Clock::time_point last{}, start{};
    std::mutex m;
};

Progress::Progress(double total_work) : st_(std::make_shared<State>()) {
    st_->total = std::max(total_work, 1.0);
    st_->tty = isatty(STDERR_FILENO) != 0;
    st_->start = Clock::now();
}

void Progress::begin(const std::string& label) {
    std::lock_guard<std::mutex> g(st_->m);
    st_->label = label;
    draw(true);
}

void Progress::add(double work) {
    std::lock_guard<std::mutex> g(st_->m);  // once per image row: no contention to speak of
    st_->done += work;
    draw(false);
}

void Progress::end() {
    std::lock_guard<std::mutex> g(st_->m);
    if (!st_->tty) {
        const double el = std::chrono::duration<double>(Clock::now() - st_->start).count();
        std::fprintf(stderr, "[%3.0f%%] %6.1fs  %s done\n", 100.0 * std::min(st_->done / st_->total, 1.0), el,
                     st_->label.c_str());
    }
}

void Progress::finish() {
    std::lock_guard<std::mutex> g(st_->m);
    if (st_->tty) std::fprintf(stderr, "\r%100s\r", "");
}

void Progress::draw(bool force) {
    if (!st_->tty) return;
    const Clock::time_point now = Clock::now();
    if (!force && now - st_->last < std::chrono::milliseconds(200)) return;
    st_->last = now;
    const double f = std::min(st_->done / st_->total, 1.0);
    const int width = 30, fill = static_cast<int>(f * width + 0.5);
    char bar[width + 1];
    for (int i = 0; i < width; ++i) bar[i] = i < fill ? '#' : '.';
    bar[width] = 0;
    const double el = std::chrono::duration<double>(now - st_->start).count();
    std::fprintf(stderr, "\r[%s] %3.0f%% %5.1fs  %-40.40s", bar, 100.0 * f, el, st_->label.c_str());
    std::fflush(stderr);
}

namespace {
/// Calls row(y) for every row on `threads` threads (rows handed out by an atomic counter).
template <class Row> void parallel_rows(int height, int threads, const Row& row) {
    std::atomic<int> next_row{0};
    auto work = [&]() {
        for (int y; (y = next_row.fetch_add(1)) < height;) row(y);
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}
}  // namespace

double render(const Scene& scene, Kind kind, int width, int height, const std::vector<int>& marks, int threads,
              std::uint32_t salt, Progress& progress, std::vector<Image>& out) {
    const int nm = static_cast<int>(marks.size());
    out.assign(marks.size(), Image(width, height));
    double seconds = -1.0;
    auto run = [&](const auto& factory) {
        const auto t0 = Clock::now();
        parallel_rows(height, threads, [&](int y) {
            std::vector<float> vals(marks.size());
            for (int x = 0; x < width; ++x) {
                shade_pixel(scene, factory, x, y, width, height, marks.data(), nm, salt, vals.data());
                for (int k = 0; k < nm; ++k) out[k].at(x, y) = vals[k];
            }
            progress.add(static_cast<double>(width) * marks.back());
        });
        seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    };
    if (scene.type == SceneType::sphere_light) with_sphere_factory(kind, run);
    else with_factory(kind, run);
    return seconds;
}

Image render_sphere_reference(const Scene& scene, int width, int height, int spp, int threads, std::uint32_t salt,
                              Progress& progress, Image& exact) {
    Image img(width, height);
    exact = Image(width, height);
    const SphereMapFactory factory{map_choice(Kind::tabulated)};
    parallel_rows(height, threads, [&](int y) {
        for (int x = 0; x < width; ++x) {
            vec3 o, d, p, n;
            bool ground = false;
            camera_ray(scene, x, y, width, height, o, d);
            if (!hit_surface(scene, o, d, p, n, ground)) continue;  // 0 (sky or emitter)
            if (ground && sphere_reference_is_exact(scene, glm::dvec3(p))) {
                img.at(x, y) = static_cast<float>(sphere_radiance_exact(scene, glm::dvec3(p)));
                exact.at(x, y) = 1.0f;
                continue;
            }
            shade_pixel(scene, factory, x, y, width, height, &spp, 1, salt, &img.at(x, y));
        }
        progress.add(static_cast<double>(width) * spp);
    });
    return img;
}

Canvas display(const Scene& scene, const Image& img, float exposure) {
    Canvas c = tonemap(img, exposure, scene.tint);
    if (scene.type != SceneType::sphere_light) return c;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            vec3 o, d;
            camera_ray(scene, x, y, img.width, img.height, o, d);
            if (hits_emitter_first(scene, o, d)) c.at(x, y) = rgb8(255);
        }
    return c;
}

Image render_plane_exact(const Scene& scene, int width, int height) {
    Image img(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            vec3 o, d, p, n;
            bool ground;
            camera_ray(scene, x, y, width, height, o, d);
            img.at(x, y) = hit_surface(scene, o, d, p, n, ground)
                               ? static_cast<float>(plane_radiance_exact(scene, glm::dvec3(p)))
                               : 0.0f;
        }
    return img;
}

}  // namespace demo
