// apse demo — renders the paper's comparison with every sampler and writes pictures and tables.
// SPDX-License-Identifier: MIT
//
//   apse_demo [--out DIR] [--quick] [--width W] [--height H] [--spp N] [--max-spp M]
//             [--ref-spp R] [--threads T]
//
// Writes into DIR (default apse_demo_out): <scene>_<sampler>.png, <scene>_reference.png,
// <scene>_comparison.png, convergence.png, results.md. Returns non-zero if a self-check fails
// or a file could not be written.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "figures.hpp"
#include "render.hpp"

using namespace demo;

namespace {

struct Options {
    std::string out = "apse_demo_out";
    int width = 320, height = 240, spp = 16, max_spp = 64, ref_spp = 512, threads = 0;
    bool quick = false;
};

int usage() {
    std::fprintf(stderr,
                 "usage: apse_demo [--out DIR] [--quick] [--width W] [--height H] [--spp N] [--max-spp M]\n"
                 "                 [--ref-spp R] [--threads T]\n");
    return 2;
}

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

std::string file_name(const std::string& s) {
    std::string r;
    for (char c : s) r += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    return r;
}

struct Row {
    std::string sampler;
    double relmse, seconds, efficiency;
    double relmse_exact;  // over the pixels with a closed-form reference (scene 4)
};

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        const char* v = nullptr;
        if (a == "--quick") opt.quick = true;
        else if (a == "--out" && (v = next())) opt.out = v;
        else if (a == "--width" && (v = next())) opt.width = std::atoi(v);
        else if (a == "--height" && (v = next())) opt.height = std::atoi(v);
        else if (a == "--spp" && (v = next())) opt.spp = std::atoi(v);
        else if (a == "--max-spp" && (v = next())) opt.max_spp = std::atoi(v);
        else if (a == "--ref-spp" && (v = next())) opt.ref_spp = std::atoi(v);
        else if (a == "--threads" && (v = next())) opt.threads = std::atoi(v);
        else return usage();
    }
    if (opt.quick) {
        opt.width = 64;
        opt.height = 48;
        opt.spp = 4;
        opt.max_spp = 8;
        opt.ref_spp = 32;
    }
    if (opt.threads <= 0) opt.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (opt.width < 16 || opt.height < 16 || opt.spp < 1 || opt.max_spp < 1 || opt.ref_spp < 1) return usage();
    std::error_code ec;
    std::filesystem::create_directories(opt.out, ec);
    if (ec) {
        std::fprintf(stderr, "apse_demo: cannot create %s: %s\n", opt.out.c_str(), ec.message().c_str());
        return 1;
    }

    const std::vector<Scene> scenes = make_scenes();

    // Scene 1's and scene 4's closed-form references, checked against quadrature first.
    const double check = plane_reference_selfcheck(scenes[0]);
    if (!(check < 1e-4)) {
        std::fprintf(stderr, "apse_demo: closed-form disk irradiance disagrees with quadrature (%g)\n", check);
        return 1;
    }
    const double sphere_check = sphere_reference_selfcheck(scenes[3]);
    if (!(sphere_check < 1e-4)) {
        std::fprintf(stderr, "apse_demo: closed-form sphere irradiance disagrees with quadrature (%g)\n", sphere_check);
        return 1;
    }

    std::vector<int> marks;
    for (int n = 1; n <= opt.max_spp; n *= 2) marks.push_back(n);
    const double px = static_cast<double>(opt.width) * opt.height;
    double total = 0;
    for (const Scene& s : scenes)
        total += px * (static_cast<double>(s.kinds.size()) * (2 * opt.spp + marks.back()) +
                       (s.type == SceneType::plane ? 0 : opt.ref_spp));
    Progress progress(total);

    std::vector<std::string> written;
    bool ok = true;
    auto save = [&](const Canvas& c, const std::string& name, bool grey = true) {
        const std::string path = (std::filesystem::path(opt.out) / name).string();
        if (c.write_png(path, grey)) written.push_back(path);
        else {
            std::fprintf(stderr, "apse_demo: could not write %s\n", path.c_str());
            ok = false;
        }
    };

    std::ostringstream md;
    md << "# apse demo results\n\n"
       << opt.width << "×" << opt.height << " pixels, " << opt.spp << " samples per pixel (scrambled Sobol' points, "
       << "the same for every sampler), " << opt.threads << " threads, float. relMSE = mean over pixels of "
       << "(I − R)² / (R² + 0.01 mean(R)²); time = wall time of a whole render at this spp (best of three measurements); efficiency = 1/(relMSE·time) "
       << "relative to the first sampler of the table (area sampling; for the sphere light pbrt-v4's uniform cone sampling, "
       << "what renderers use today).\n";
    std::vector<std::pair<std::string, std::vector<Series>>> plots;
    std::printf("apse demo: %d×%d, %d spp, %d threads\n", opt.width, opt.height, opt.spp, opt.threads);

    for (const Scene& scene : scenes) {
        Image ref, exact;  // exact: the pixels whose reference is a closed form (scene 4; empty otherwise)
        std::string ref_note;
        std::string ref_label = std::to_string(opt.ref_spp) + " spp";
        if (scene.type == SceneType::plane) {
            ref = render_plane_exact(scene, opt.width, opt.height);
            ref_note = "closed form (checked against quadrature: max rel. error " + fmt("%.1e", check) + ")";
            ref_label = "closed form";
        } else if (scene.type == SceneType::sphere_light) {
            progress.begin(scene.name + ": reference");
            ref = render_sphere_reference(scene, opt.width, opt.height, opt.ref_spp, opt.threads, 0x9e3779b9u,
                                          progress, exact);
            progress.end();
            double share = 0.0;
            for (float v : exact.px) share += v;
            share /= static_cast<double>(exact.px.size());
            ref_note = "closed form of the irradiance from a sphere cut by the horizon (checked against quadrature: "
                       "max rel. error " + fmt("%.1e", sphere_check) + ") on the ground where nothing occludes the "
                       "light (" + fmt("%.0f", 100.0 * share) + " % of the pixels), elsewhere " +
                       std::to_string(opt.ref_spp) + " spp with " + kind_name(Kind::tabulated) + " (independent points)";
            ref_label = "closed form + " + ref_label;
        } else {
            progress.begin(scene.name + ": reference");
            std::vector<Image> r;
            // the most efficient unbiased sampler, with points independent of the judged renders
            const Kind ref_kind = Kind::tabulated;
            render(scene, ref_kind, opt.width, opt.height, {opt.ref_spp}, opt.threads, 0x9e3779b9u, progress, r);
            progress.end();
            ref = r.front();
            ref_note = std::to_string(opt.ref_spp) + " spp with " +
                       kind_name(ref_kind) + " (independent points)";
        }
        const float exposure = auto_exposure(ref);
        std::vector<Panel> panels;
        panels.push_back({display(scene, ref, exposure), "REFERENCE", ref_label});
        save(panels.back().picture, scene.name + "_reference.png");

        std::vector<Row> rows;
        std::vector<Series> series;
        const std::vector<Kind>& kinds = scene.kinds;
        for (std::size_t k = 0; k < kinds.size(); ++k) {
            const std::string name = kind_name(kinds[k]);
            progress.begin(scene.name + ": " + name);
            std::vector<Image> img, conv;
            const double t_img = render(scene, kinds[k], opt.width, opt.height, {opt.spp}, opt.threads, 1u, progress, img);
            const double t_conv = render(scene, kinds[k], opt.width, opt.height, marks, opt.threads, 2u, progress, conv);
            std::vector<Image> again;  // the same render once more, for the timing only
            const double t_again = render(scene, kinds[k], opt.width, opt.height, {opt.spp}, opt.threads, 1u, progress, again);
            // time per opt.spp samples per pixel: the best of three measurements (the machine may be shared)
            const double sec = std::min({t_img, t_again, t_conv * opt.spp / marks.back()});
            progress.end();
            if (t_img < 0.0) {
                std::fprintf(stderr, "apse_demo: no %s sampler for scene %s\n", name.c_str(), scene.name.c_str());
                return 1;
            }
            const double e = rel_mse(img.front(), ref);
            rows.push_back({name, e, sec, 0.0, exact.px.empty() ? 0.0 : rel_mse(img.front(), ref, exact)});
            // a colour per sampler kind (cone takes area's: the same role)
            const int colour = kinds[k] == Kind::cone ? static_cast<int>(Kind::area) : static_cast<int>(kinds[k]);
            Series s{name, series_colour(colour), {}, {}, kinds[k] == Kind::tabulated};
            for (std::size_t m = 0; m < marks.size(); ++m) {
                s.x.push_back(marks[m]);
                s.y.push_back(rel_mse(conv[m], ref));
            }
            series.push_back(s);
            panels.push_back({display(scene, img.front(), exposure), name, ""});
            save(panels.back().picture, scene.name + "_" + file_name(name) + ".png");
        }
        const double base = 1.0 / (rows.front().relmse * rows.front().seconds);
        for (std::size_t k = 0; k < rows.size(); ++k) {
            rows[k].efficiency = 1.0 / (rows[k].relmse * rows[k].seconds) / base;
            panels[k + 1].sublabel = "RELMSE " + fmt("%.2e", rows[k].relmse) + "  EFF " + fmt("%.2fx", rows[k].efficiency);
        }
        save(comparison_figure(panels, 2, scene.inset, 4, scene.title + " - " + std::to_string(opt.spp) + " spp"),
             scene.name + "_comparison.png");
        plots.emplace_back(scene.label, series);

        const bool split = !exact.px.empty();
        md << "\n## " << scene.title << "\n\nReference: " << ref_note << ".";
        if (split)
            md << " The last column is the relMSE over the closed-form pixels only: the horizon-cut cap without "
                  "occlusion (where cosine-weighted sampling has zero variance).";
        md << "\n\n| sampler | relMSE | relMSE vs " << rows.front().sampler << " | time (s) | efficiency vs "
           << rows.front().sampler << " |" << (split ? " relMSE, unoccluded |\n|---|---|---|---|---|---|\n" : "\n|---|---|---|---|---|\n");
        for (const Row& r : rows) {
            md << "| " << r.sampler << " | " << fmt("%.3e", r.relmse) << " | " << fmt("%.3g", r.relmse / rows.front().relmse)
               << " | " << fmt("%.3f", r.seconds) << " | " << fmt("%.2f", r.efficiency) << " |";
            if (split) md << " " << fmt("%.2e", r.relmse_exact) << " |";
            md << "\n";
        }
    }
    progress.finish();
    save(convergence_plot(plots), "convergence.png", false);

    const std::string md_path = (std::filesystem::path(opt.out) / "results.md").string();
    {
        std::ofstream f(md_path);
        f << md.str();
        if (!f) ok = false;
        else written.push_back(md_path);
    }
    std::printf("%s\n", md.str().c_str());
    for (const std::string& p : written)
        if (!std::filesystem::exists(p) || std::filesystem::file_size(p) == 0) ok = false;
    std::printf("apse demo: %zu files written to %s\n", written.size(), std::filesystem::absolute(opt.out).string().c_str());
    return ok ? 0 : 1;
}
