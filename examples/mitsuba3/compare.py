#!/usr/bin/env python3
"""Renders apse's comparison inside Mitsuba 3: each scene of scenes.py with every light sampler,
at equal samples (16 spp) and at equal time (the time of Mitsuba's light at 64 spp), against a high-spp reference; writes PNG
comparisons and a Markdown table (relMSE, time, efficiency), printing one progress line per render.

    python3 tools/mitsuba3_test.py setup --dir build/release/mitsuba3   # venv + wheels + plugin (as the tests)
    build/release/mitsuba3/venv/bin/python examples/mitsuba3/compare.py --out build/release/mitsuba3/compare

relMSE = mean over pixels of (I - R)^2 / (R^2 + 0.01 mean(R)^2) on the RGB average, as the demo;
time = CPU time of mi.render, all its threads summed (the smallest of --repeats runs: CPU time
is far less disturbed than wall time by other programs on a shared machine); efficiency =
1/(relMSE time),
relative to Mitsuba's own light; the reference: cosine tabulated LD-radial at --ref-spp (another
seed). Directly visible lights are rendered black (hide_emitters) so
that the error measures light sampling, not the anti-aliasing of the lights' silhouettes.
"""
import argparse
import math
import os
import re
import sys
import time

import numpy as np
import mitsuba as mi

mi.set_variant("scalar_rgb")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import scenes  # noqa: E402

LABELS = {"mitsuba": "Mitsuba area", "area": "apse_disk area", "radial": "radial",
          "ld_radial": "LD-radial", "parallel": "parallel", "tabulated_ld_radial": "tabulated LD-radial",
          "cosine_ld_radial": "cosine LD-radial", "cosine_tabulated_ld_radial": "cosine tabulated LD-radial"}


def load_font():
    """The demo's 5x7 bitmap font (examples/demo/font.hpp): {character: 7x5 boolean array}."""
    with open(os.path.join(HERE, "..", "demo", "font.hpp")) as f:
        glyphs = re.findall(r"\{'(.)', \"([.#]{35})\"\}", f.read())
    return {c: np.array([ch == "#" for ch in rows]).reshape(7, 5) for c, rows in glyphs}


def text_band(lines, width, font, height=22):
    """A white band `height` pixels high and `width` wide with up to two lines of black text
    (the demo's font: lower case drawn as upper case, except x)."""
    band = np.ones((height, width), np.float32)
    for k, line in enumerate(lines[:2]):
        x, y = 2, 2 + 10 * k
        for ch in line:
            g = font.get(ch if ch == "x" else ch.upper())
            if g is not None and x + 5 <= width:
                band[y:y + 7, x:x + 5][g] = 0.0
            x += 6
    return band


def rel_mse(img, ref):
    """Mean over pixels of (I - R)^2 / (R^2 + 0.01 mean(R)^2) on the RGB average (as the demo)."""
    i, r = img.mean(axis=2), ref.mean(axis=2)
    return float((((i - r) ** 2) / (r ** 2 + 0.01 * r.mean() ** 2)).mean())


def timed_render(scene, spp, seed, repeats):
    best, img = float("inf"), None
    for _ in range(repeats):
        t0 = time.process_time()
        img = np.array(mi.render(scene, spp=spp, seed=seed))
        best = min(best, time.process_time() - t0)
    return img, best


def nearest_square(x):
    """The `stratified` sampler takes square sample counts: the square nearest to x (>= 1)."""
    k = max(1, int(round(math.sqrt(max(x, 1.0)))))
    return k * k


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(HERE, "..", "..", "build", "release", "mitsuba3", "compare"))
    ap.add_argument("--plugins", default=os.path.join(HERE, "..", "..", "build", "release", "mitsuba3", "plugin"),
                    help="directory holding plugins/apse_disk.so (tools/mitsuba3_test.py setup --dir D: D/plugin)")
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--height", type=int, default=120)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--ref-spp", type=int, default=1024)
    ap.add_argument("--time-spp", type=int, default=64,
                    help="equal-time renders: the budget is Mitsuba's light at this many spp")
    ap.add_argument("--repeats", type=int, default=3, help="timed runs per render (the fastest counts)")
    ap.add_argument("--scenes", default=",".join(scenes.SCENES))
    a = ap.parse_args()
    mi.file_resolver().append(os.path.abspath(a.plugins))
    os.makedirs(a.out, exist_ok=True)

    names = a.scenes.split(",")
    lights = scenes.LIGHTS
    total = len(names) * (1 + 2 * len(lights))
    done = 0
    md = []
    font = load_font()

    def progress(msg):
        nonlocal done
        done += 1
        print("[%2d/%d] %s" % (done, total, msg), flush=True)

    for name in names:
        def load(light, spp):
            return mi.load_dict(scenes.scene_dict(name, light, a.width, a.height, spp, hide_emitters=True))

        t0 = time.perf_counter()
        # the reference: the sampler of least noise (cosine-weighted; in the medium, which has no
        # receiver normals, the plain map), so that its own noise stays below the errors measured
        ref = np.array(mi.render(load("cosine_tabulated_ld_radial", a.ref_spp), seed=1_000_003))
        progress("%-7s reference: cosine tabulated LD-radial, %d spp, %.1f s" % (name, a.ref_spp, time.perf_counter() - t0))

        rows, eq_spp, eq_time = {}, {}, {}
        for light in lights:
            scene = load(light, a.spp)
            img, t = timed_render(scene, a.spp, 0, a.repeats)
            rows[light] = {"spp_img": img, "t": t, "e": rel_mse(img, ref), "scene": scene}
            progress("%-7s %-26s %4d spp: %6.3f s, relMSE %.3e" % (name, LABELS[light], a.spp, t, rows[light]["e"]))
        # equal time: Mitsuba's light at --time-spp, the others at the square sample count whose
        # time (from the per-sample cost measured above) comes nearest to that
        budget = rows["mitsuba"]["t"] * a.time_spp / a.spp
        for light in lights:
            spp = nearest_square(budget / (rows[light]["t"] / a.spp))
            img, t = timed_render(rows[light]["scene"], spp, 0, a.repeats)
            rows[light].update(time_img=img, time_spp=spp, time_t=t, time_e=rel_mse(img, ref))
            progress("%-7s %-26s %4d spp (equal time): %6.3f s, relMSE %.3e" % (name, LABELS[light], spp, t,
                                                                              rows[light]["time_e"]))

        # pictures: reference, then every light; top row equal samples, bottom row equal time,
        # each picture under its sampler's name, sample count and relMSE. Grey scale (every
        # colour in the scenes is grey), exposed so that the reference's 99th percentile is white.
        grey = lambda img: img.mean(axis=2)
        exposure = 1.0 / max(float(np.quantile(grey(ref), 0.99)), 1e-6)
        shown = lambda img: np.clip(exposure * grey(img), 0, 1)
        w = ref.shape[1]
        top = [(shown(ref), ["reference", "%d spp" % a.ref_spp])]
        top += [(shown(rows[l]["spp_img"]), [LABELS[l], "%d spp relMSE %.2e" % (a.spp, rows[l]["e"])]) for l in lights]
        bottom = [(np.ones_like(grey(ref)), ["equal time:", "as Mitsuba at %d spp" % a.time_spp])]
        bottom += [(shown(rows[l]["time_img"]), [LABELS[l], "%d spp relMSE %.2e" % (rows[l]["time_spp"], rows[l]["time_e"])])
                   for l in lights]
        strip = lambda row: np.concatenate([np.concatenate([text_band(t, w, font), img], axis=0) for img, t in row], axis=1)
        picture = np.concatenate([strip(top), strip(bottom)], axis=0).astype(np.float32)[:, :, None]
        mi.Bitmap(picture, mi.Bitmap.PixelFormat.Y).convert(
            mi.Bitmap.PixelFormat.Y, mi.Struct.Type.UInt8, srgb_gamma=True).write(
            os.path.join(a.out, "%s_comparison.png" % name))

        base = rows["mitsuba"]
        eff = lambda r: 1.0 / (r["e"] * r["t"])
        md.append("#### %s\n" % name)
        md.append("| sampler | relMSE, %d spp | vs Mitsuba | CPU time (s) | efficiency vs Mitsuba | "
                  "efficiency vs apse_disk area | equal time: spp | CPU time (s) | relMSE | vs Mitsuba |" % a.spp)
        md.append("|---|---|---|---|---|---|---|---|---|---|")
        for l in lights:
            r = rows[l]
            md.append("| %s | %.3e | %.3g | %.3f | %.2f | %.2f | %d | %.3f | %.3e | %.3g |"
                      % (LABELS[l], r["e"], r["e"] / base["e"], r["t"], eff(r) / eff(base), eff(r) / eff(rows["area"]),
                         r["time_spp"], r["time_t"], r["time_e"], r["time_e"] / base["time_e"]))
        md.append("")

    md.append("%dx%d pixels, `stratified` sampler, reference: cosine tabulated LD-radial at %d spp (another seed); "
              "time: CPU time of mi.render (threads summed), smallest of %d runs; efficiency = 1/(relMSE time); "
              "apse_disk area: the same area sampling as Mitsuba's light, of one two-sided disk (Mitsuba's is two "
              "back-to-back one-sided disks)." % (a.width, a.height, a.ref_spp, a.repeats))
    text = "\n".join(md)
    with open(os.path.join(a.out, "results.md"), "w") as f:
        f.write(text + "\n")
    print(text)
    print("pictures and table in " + os.path.abspath(a.out))


if __name__ == "__main__":
    main()
