// apse demo — images, tone mapping, drawing primitives and PNG output.
// SPDX-License-Identifier: MIT
#pragma once

/// @file image.hpp
/// `Image`: a float (radiance) image; `Canvas`: an 8-bit sRGB RGB picture with the few drawing
/// primitives the figures need (blit, rectangles, lines, 5×7 text); PNG through stb_image_write.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace demo {

struct Image {
    Image() = default;
    Image(int w, int h) : width(w), height(h), px(static_cast<std::size_t>(w) * h, 0.0f) {}
    float& at(int x, int y) { return px[static_cast<std::size_t>(y) * width + x]; }
    float at(int x, int y) const { return px[static_cast<std::size_t>(y) * width + x]; }
    int width = 0, height = 0;
    std::vector<float> px;
};

/// Relative MSE of `img` against `ref`: mean over pixels of (img − ref)² / (ref² + eps), with
/// eps = 1e-2 × (mean of ref)² (keeps dark pixels from dominating).
double rel_mse(const Image& img, const Image& ref);

/// rel_mse over the pixels where mask > 0 only (eps from the mean of ref over them; 0 if there
/// are none); an empty mask (Image()) selects every pixel.
double rel_mse(const Image& img, const Image& ref, const Image& mask);

/// The exposure that maps the reference's 99th percentile of lit pixels to display value ~0.8.
float auto_exposure(const Image& ref);

/// An 8-bit sRGB colour.
struct rgb8 {
    constexpr rgb8() = default;
    constexpr rgb8(int r_, int g_, int b_)
        : c{static_cast<std::uint8_t>(r_), static_cast<std::uint8_t>(g_), static_cast<std::uint8_t>(b_)} {}
    constexpr explicit rgb8(int v) : rgb8(v, v, v) {}
    std::uint8_t& operator[](int k) { return c[k]; }
    std::uint8_t c[3] = {0, 0, 0};
};
static_assert(sizeof(rgb8) == 3, "rgb8 must be packed for stb");

struct Canvas {
    Canvas(int w, int h, rgb8 fill = rgb8(255));
    rgb8& at(int x, int y) { return px[static_cast<std::size_t>(y) * width + x]; }
    int width, height;
    std::vector<rgb8> px;

    /// Copies `src` (or its rectangle sx, sy, sw, sh) to (x, y), magnified `zoom` times.
    void blit(const Canvas& src, int x, int y, int zoom = 1);
    void blit(const Canvas& src, int sx, int sy, int sw, int sh, int x, int y, int zoom);
    void fill_rect(int x, int y, int w, int h, rgb8 c);
    void frame_rect(int x, int y, int w, int h, rgb8 c, int thickness = 1);
    void line(float x0, float y0, float x1, float y1, rgb8 c, float thickness = 2.0f);
    /// Text in the 5×7 font, `scale` pixels per font pixel; returns the width drawn.
    int text(int x, int y, const std::string& s, rgb8 c, int scale = 1);
    static int text_width(const std::string& s, int scale = 1) { return static_cast<int>(s.size()) * 6 * scale; }
    /// Writes an RGB PNG, or an 8-bit grey one (luma) if `grey` (a third of the size: the
    /// renders are monochrome).
    bool write_png(const std::string& path, bool grey = false) const;
};

/// Tone maps radiance to sRGB: 1 − exp(−exposure·L) per channel of tint·L, then sRGB gamma.
Canvas tonemap(const Image& img, float exposure, glm::vec3 tint);

}  // namespace demo
