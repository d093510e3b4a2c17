// apse demo — the comparison figure and the convergence plot.
// SPDX-License-Identifier: MIT
#include "figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace demo {

rgb8 series_colour(int i) {
    static const rgb8 c[] = {rgb8(200, 40, 40),  rgb8(230, 150, 20), rgb8(40, 110, 200),
                             rgb8(30, 150, 60),  rgb8(140, 60, 170), rgb8(20, 170, 170),
                             rgb8(120, 120, 120)};
    return c[i % 7];
}

Canvas comparison_figure(const std::vector<Panel>& panels, int columns, glm::vec2 inset, int zoom,
                         const std::string& title) {
    // Each panel: the picture decimated 2× (nearest: the noise keeps its per-pixel look) with
    // the inset's region outlined, and next to it the region at full resolution, zoom× (the
    // region is 2/zoom of the picture's size, so both halves have the same height).
    const int W = panels.front().picture.width, H = panels.front().picture.height;
    const int w = W / 2, h = H / 2;
    const int iw = w / zoom * 1, ih = h / zoom * 1;  // region size in full-resolution pixels
    const int cell_w = w + 2 + iw * zoom, pad = 8, label_h = 22, title_h = 36;
    const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
    Canvas fig(columns * (cell_w + pad) + pad, title_h + rows * (h + label_h + pad) + pad, rgb8(255));
    fig.text(pad, 6, title, rgb8(0), 2);
    fig.text(pad, 24, "Right half of each panel: the white box at full resolution enlarged " + std::to_string(zoom) +
                          "x (left half: every second pixel)", rgb8(70), 1);
    const int sx = std::clamp(static_cast<int>(inset.x * static_cast<float>(W)) - iw / 2, 0, W - iw);
    const int sy = std::clamp(static_cast<int>(inset.y * static_cast<float>(H)) - ih / 2, 0, H - ih);
    for (std::size_t k = 0; k < panels.size(); ++k) {
        const int col = static_cast<int>(k) % columns, row = static_cast<int>(k) / columns;
        const int x0 = pad + col * (cell_w + pad), y0 = title_h + row * (h + label_h + pad);
        const Canvas& pic = panels[k].picture;
        fig.text(x0, y0 + 2, panels[k].label, rgb8(0), 1);
        fig.text(x0, y0 + 12, panels[k].sublabel, rgb8(70), 1);
        const int py = y0 + label_h;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) fig.at(x0 + i, py + j) = pic.px[static_cast<std::size_t>(2 * j) * W + 2 * i];
        fig.frame_rect(x0 + sx / 2 - 1, py + sy / 2 - 1, iw / 2 + 2, ih / 2 + 2, rgb8(255), 1);
        fig.blit(pic, sx, sy, iw, ih, x0 + w + 2, py, zoom);
    }
    return fig;
}

namespace {
std::string decade_label(int e) {
    char b[16];
    if (e >= 0 && e <= 3) std::snprintf(b, sizeof b, "%d", static_cast<int>(std::lround(std::pow(10.0, e))));
    else std::snprintf(b, sizeof b, "1E%d", e);
    return b;
}
}  // namespace

Canvas convergence_plot(const std::vector<std::pair<std::string, std::vector<Series>>>& plots) {
    const int pw = 330, ph = 270, left = 44, right = 10, top = 26, bottom = 30, legend_h = 20;
    Canvas fig(static_cast<int>(plots.size()) * pw + 10, ph + legend_h + 24, rgb8(255));
    fig.text(8, 4, "RELMSE VS SAMPLES PER PIXEL (LOG-LOG)", rgb8(0), 2);
    for (std::size_t p = 0; p < plots.size(); ++p) {
        const auto& series = plots[p].second;
        double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
        for (const Series& s : series)
            for (std::size_t i = 0; i < s.x.size(); ++i) {
                if (!(s.y[i] > 0)) continue;
                xmin = std::min(xmin, s.x[i]);
                xmax = std::max(xmax, s.x[i]);
                ymin = std::min(ymin, s.y[i]);
                ymax = std::max(ymax, s.y[i]);
            }
        if (!(xmax > 0)) continue;
        const double lx0 = std::log10(xmin), lx1 = std::max(std::log10(xmax), lx0 + 0.1);
        const int e0 = static_cast<int>(std::floor(std::log10(ymin))), e1 = static_cast<int>(std::ceil(std::log10(ymax)));
        const double ly0 = e0, ly1 = std::max(e1, e0 + 1);
        const int ox = 10 + static_cast<int>(p) * pw + left, oy = 24 + top;
        const int aw = pw - left - right, ah = ph - top - bottom;
        auto X = [&](double x) { return static_cast<float>(ox + (std::log10(x) - lx0) / (lx1 - lx0) * aw); };
        auto Y = [&](double y) { return static_cast<float>(oy + ah - (std::log10(y) - ly0) / (ly1 - ly0) * ah); };
        fig.text(ox, oy - 14, plots[p].first, rgb8(0), 1);
        // grid and ticks
        for (int e = static_cast<int>(ly0); e <= static_cast<int>(ly1); ++e) {
            const int y = static_cast<int>(Y(std::pow(10.0, e)));
            fig.fill_rect(ox, y, aw, 1, rgb8(225));
            const std::string l = decade_label(e);
            fig.text(ox - 4 - Canvas::text_width(l), y - 3, l, rgb8(0));
        }
        for (double x = xmin; x <= xmax * 1.0001; x *= 2) {
            const int xi = static_cast<int>(X(x));
            fig.fill_rect(xi, oy, 1, ah, rgb8(235));
            const std::string l = std::to_string(static_cast<int>(x));
            fig.text(xi - Canvas::text_width(l) / 2, oy + ah + 5, l, rgb8(0));
        }
        fig.text(ox + aw / 2 - Canvas::text_width("spp") / 2, oy + ah + 15, "spp", rgb8(0));
        fig.frame_rect(ox, oy, aw + 1, ah + 1, rgb8(0));
        // solid curves first, dashed ones on top (so coinciding curves stay visible)
        for (int pass = 0; pass < 2; ++pass)
            for (const Series& s : series) {
                if (s.dashed != (pass == 1)) continue;
                for (std::size_t i = 0; i + 1 < s.x.size(); ++i) {
                    if (!(s.y[i] > 0 && s.y[i + 1] > 0)) continue;
                    const float xa = X(s.x[i]), ya = Y(s.y[i]), xb = X(s.x[i + 1]), yb = Y(s.y[i + 1]);
                    if (!s.dashed) {
                        fig.line(xa, ya, xb, yb, s.colour, 3.0f);
                        continue;
                    }
                    const int n = std::max(1, static_cast<int>(std::hypot(xb - xa, yb - ya) / 6.0f));
                    for (int d = 0; d < n; d += 2) {
                        const float t0 = static_cast<float>(d) / n, t1 = static_cast<float>(d + 1) / n;
                        fig.line(xa + t0 * (xb - xa), ya + t0 * (yb - ya), xa + t1 * (xb - xa), ya + t1 * (yb - ya),
                                 s.colour, 2.0f);
                    }
                }
            }
        for (const Series& s : series) {
            for (std::size_t i = 0; i < s.x.size(); ++i)
                if (s.y[i] > 0) fig.fill_rect(static_cast<int>(X(s.x[i])) - 2, static_cast<int>(Y(s.y[i])) - 2, 5, 5, s.colour);
        }
    }
    // legend: every series name once, in the order the plots first show it
    int lx = 14;
    const int ly = ph + 24 + 4;
    std::vector<std::string> shown;
    for (const auto& plot : plots)
        for (const Series& s : plot.second) {
            if (std::find(shown.begin(), shown.end(), s.name) != shown.end()) continue;
            shown.push_back(s.name);
            fig.fill_rect(lx, ly, 18, 7, s.colour);
            lx += 24;
            lx += fig.text(lx, ly, s.name, rgb8(0)) + 14;
        }
    return fig;
}

}  // namespace demo
