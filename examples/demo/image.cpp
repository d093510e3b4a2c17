// apse demo — images, tone mapping, drawing primitives and PNG output.
// SPDX-License-Identifier: MIT
#include "image.hpp"

#include <algorithm>
#include <cmath>

#include "font.hpp"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wtype-limits"
#endif
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO_WARNINGS
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace demo {

double rel_mse(const Image& img, const Image& ref) { return rel_mse(img, ref, Image()); }

double rel_mse(const Image& img, const Image& ref, const Image& mask) {
    auto in = [&](std::size_t i) { return mask.px.empty() || mask.px[i] > 0.0f; };
    double mean = 0.0, count = 0.0;
    for (std::size_t i = 0; i < ref.px.size(); ++i)
        if (in(i)) {
            mean += ref.px[i];
            count += 1.0;
        }
    if (!(count > 0.0)) return 0.0;
    mean /= count;
    const double eps = 1e-2 * mean * mean;
    double s = 0.0;
    for (std::size_t i = 0; i < ref.px.size(); ++i) {
        if (!in(i)) continue;
        const double d = static_cast<double>(img.px[i]) - ref.px[i];
        s += d * d / (static_cast<double>(ref.px[i]) * ref.px[i] + eps);
    }
    return s / count;
}

float auto_exposure(const Image& ref) {
    std::vector<float> lit;
    for (float v : ref.px)
        if (v > 0.0f) lit.push_back(v);
    if (lit.empty()) return 1.0f;
    const std::size_t k = lit.size() * 99 / 100;
    std::nth_element(lit.begin(), lit.begin() + static_cast<std::ptrdiff_t>(k), lit.end());
    return 1.6f / std::max(lit[k], 1e-12f);  // 1 − e^−1.6 ≈ 0.8
}

static std::uint8_t to_srgb8(float v) {
    v = std::min(std::max(v, 0.0f), 1.0f);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(s * 255.0f + 0.5f);
}

Canvas tonemap(const Image& img, float exposure, glm::vec3 tint) {
    Canvas c(img.width, img.height);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float v = std::max(img.at(x, y), 0.0f) * exposure;
            rgb8& p = c.at(x, y);
            for (int k = 0; k < 3; ++k) p[k] = to_srgb8(1.0f - std::exp(-v * tint[k]));
        }
    return c;
}

Canvas::Canvas(int w, int h, rgb8 fill) : width(w), height(h), px(static_cast<std::size_t>(w) * h, fill) {}

void Canvas::blit(const Canvas& src, int x, int y, int zoom) { blit(src, 0, 0, src.width, src.height, x, y, zoom); }

void Canvas::blit(const Canvas& src, int sx, int sy, int sw, int sh, int x, int y, int zoom) {
    for (int j = 0; j < sh * zoom; ++j)
        for (int i = 0; i < sw * zoom; ++i) {
            const int tx = x + i, ty = y + j, fx = sx + i / zoom, fy = sy + j / zoom;
            if (tx < 0 || ty < 0 || tx >= width || ty >= height || fx < 0 || fy < 0 || fx >= src.width ||
                fy >= src.height)
                continue;
            at(tx, ty) = src.px[static_cast<std::size_t>(fy) * src.width + fx];
        }
}

void Canvas::fill_rect(int x, int y, int w, int h, rgb8 c) {
    for (int j = std::max(y, 0); j < std::min(y + h, height); ++j)
        for (int i = std::max(x, 0); i < std::min(x + w, width); ++i) at(i, j) = c;
}

void Canvas::frame_rect(int x, int y, int w, int h, rgb8 c, int t) {
    fill_rect(x, y, w, t, c);
    fill_rect(x, y + h - t, w, t, c);
    fill_rect(x, y, t, h, c);
    fill_rect(x + w - t, y, t, h, c);
}

void Canvas::line(float x0, float y0, float x1, float y1, rgb8 c, float thickness) {
    // Stamps discs along the segment (simple, good enough for a plot).
    const float len = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, static_cast<int>(len * 2.0f));
    const float r = 0.5f * thickness;
    const int ir = static_cast<int>(std::ceil(r));
    for (int s = 0; s <= steps; ++s) {
        const float t = static_cast<float>(s) / static_cast<float>(steps);
        const float cx = x0 + t * (x1 - x0), cy = y0 + t * (y1 - y0);
        for (int j = -ir; j <= ir; ++j)
            for (int i = -ir; i <= ir; ++i) {
                const int px_ = static_cast<int>(std::lround(cx)) + i, py_ = static_cast<int>(std::lround(cy)) + j;
                if (px_ < 0 || py_ < 0 || px_ >= width || py_ >= height) continue;
                if (static_cast<float>(i * i + j * j) <= r * r + 0.25f) at(px_, py_) = c;
            }
    }
}

int Canvas::text(int x, int y, const std::string& s, rgb8 c, int scale) {
    int cx = x;
    for (char ch : s) {
        const char* rows = glyph_rows(ch);
        for (int j = 0; j < 7; ++j)
            for (int i = 0; i < 5; ++i)
                if (rows[j * 5 + i] == '#') fill_rect(cx + i * scale, y + j * scale, scale, scale, c);
        cx += 6 * scale;
    }
    return cx - x;
}

bool Canvas::write_png(const std::string& path, bool grey) const {
    stbi_write_png_compression_level = 9;
    if (!grey) return stbi_write_png(path.c_str(), width, height, 3, px.data(), width * 3) != 0;
    std::vector<std::uint8_t> g(px.size());
    for (std::size_t i = 0; i < px.size(); ++i)
        g[i] = static_cast<std::uint8_t>((54 * px[i].c[0] + 183 * px[i].c[1] + 19 * px[i].c[2] + 128) >> 8);
    return stbi_write_png(path.c_str(), width, height, 1, g.data(), width) != 0;
}

}  // namespace demo
