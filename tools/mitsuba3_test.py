#!/usr/bin/env python3
"""End-to-end tests of apse inside Mitsuba 3 (examples/mitsuba3), run by tools/test.sh through ctest.

    python3 tools/mitsuba3_test.py [--dir DIR] setup|identity|unbiased|relmse|sphere_identity|...

Every command first makes sure DIR (default build/mitsuba3) holds a venv with the pinned wheels
and the built plugins (idempotent, under a file lock, so parallel ctest runs share one set-up),
then runs one check inside the venv:

  identity : apse_disk with sampler=area renders bit-identical images to Mitsuba's own disk +
             area light (direct and path on the ground and spheres scenes, volpath in the medium);
             this also proves the build flags match the wheel.
  unbiased : pdf_direction is the density sample_direction draws from and is positive over the
             whole light (check_pdf); then every apse sampler's image mean equals the mean of
             Mitsuba's own light, within a tolerance derived from the measured noise
             (check_unbiased).
  relmse   : at 16 spp of the `stratified` sampler, every apse sampler's relMSE against a
             high-spp reference is <= 0.3x that of Mitsuba's own light on the ground scene.
  sphere_identity, sphere_unbiased, sphere_relmse: the same three for apse_sphere against
             Mitsuba's own sphere light (a sphere shape with an `area` emitter) on the `sphere`
             scene; sphere_relmse also prints each sampler's equal-time efficiency.

With --into PAGE (sphere_relmse only) the check also writes its results as a markdown table into
PAGE, replacing what stands between the page's lines `<!-- mitsuba3_test.py: sphere_relmse -->`
and `<!-- /mitsuba3_test.py: sphere_relmse -->` (as tools/bench_table.py --into does), so that
the measured table of docs/mitsuba3.md is never copied by hand:

    python3 tools/mitsuba3_test.py sphere_relmse --into docs/mitsuba3.md

Without --into nothing is written.

Exit codes: 0 pass, 1 fail, 77 skipped (a CPU the wheels cannot run on: the message, also written
to DIR/skipped.txt for tools/test.sh to show, names the missing instructions; only that is a skip,
anything else that goes wrong is a failure).
"""
import argparse
import contextlib
import fcntl
import os
import subprocess
import sys
import time

import bench_table  # tools/: the --into convention of the measured tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PINS = ["mitsuba==3.9.1", "drjit==1.5.0", "nanobind==3.1.0", "numpy==2.4.6"]
SKIP = 77
CPU_MARK = "CPU unsupported"


def log(msg):
    print(msg, flush=True)


# ------------------------------------------------------------------------------------------------
# Measured tables written --into a docs page, between its markers (the convention of
# tools/bench_table.py and tools/doc_report.hpp, with this tool's name)

TOOL = "mitsuba3_test.py"
SECTIONS = {}  # section name -> its markdown, filled by the checks that have a table


def missing_markers(text, names):
    """The sections of `names` whose markers are not both in `text`."""
    return bench_table.missing_markers(text, names, TOOL)


def write_into(page, sections):
    """Replaces each section of `page` between its markers with its markdown."""
    bench_table.write_into([page], sections, TOOL)


def run(cmd, **kw):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)


@contextlib.contextmanager
def locked(path):
    with open(path, "w") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def setup(d):
    """venv + pinned wheels + plugin in d; returns the venv's python (exits 77 on a CPU skip)."""
    os.makedirs(d, exist_ok=True)
    venv = os.path.join(d, "venv")
    py = os.path.join(venv, "bin", "python")
    with locked(os.path.join(d, ".lock")):
        t0 = time.time()
        stamp = os.path.join(venv, "apse-pins.txt")
        if not (os.path.exists(stamp) and open(stamp).read() == "\n".join(PINS)):
            if not os.path.exists(py):
                r = run([sys.executable, "-m", "venv", venv])
                if r.returncode != 0:
                    sys.exit("mitsuba3: `%s -m venv` failed (Debian: apt-get install python3-venv):\n%s"
                             % (sys.executable, r.stdout))
            log("== mitsuba3: pip install " + " ".join(PINS))
            r = run([py, "-m", "pip", "install", "-q", "--disable-pip-version-check"] + PINS)
            if r.returncode != 0:
                sys.exit("mitsuba3: pip install failed:\n" + r.stdout)
            with open(stamp, "w") as f:
                f.write("\n".join(PINS))
        bdir = os.path.join(d, "plugin")
        r = run(["cmake", "-S", os.path.join(ROOT, "examples", "mitsuba3"), "-B", bdir, "-G", "Ninja",
                 "-DCMAKE_BUILD_TYPE=Release", "-DPython_EXECUTABLE=" + py])
        if r.returncode != 0:
            if CPU_MARK in r.stdout:
                line = [l for l in r.stdout.splitlines() if CPU_MARK in l or "needs" in l]
                reason = "SKIPPED (mitsuba3 tests): " + " ".join(l.strip() for l in line)
                log(reason)
                with open(os.path.join(d, "skipped.txt"), "w") as f:  # ctest hides skipped tests' output
                    f.write(reason + "\n")
                sys.exit(SKIP)
            sys.exit("mitsuba3: configuring the plugin failed:\n" + r.stdout)
        with contextlib.suppress(FileNotFoundError):
            os.remove(os.path.join(d, "skipped.txt"))
        r = run(["cmake", "--build", bdir])
        if r.returncode != 0:
            sys.exit("mitsuba3: building the plugin failed:\n" + r.stdout)
        log("== mitsuba3: set-up ready in %.1f s (%s)" % (time.time() - t0, bdir))
    return py, bdir


# ------------------------------------------------------------------------------------------------
# The checks (run inside the venv)

def load(plugin_dir):
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    mi.file_resolver().append(plugin_dir)
    sys.path.insert(0, os.path.join(ROOT, "examples", "mitsuba3"))
    import scenes
    return mi, scenes


def check_identity(plugin_dir):
    import numpy as np
    mi, scenes = load(plugin_dir)
    ok = True
    for name, integrator in (("plane", "direct"), ("plane", "path"), ("spheres", "direct"),
                             ("spheres", "path"), ("medium", "volpath")):
        imgs = []
        for light in ("mitsuba", "area"):
            d = scenes.scene_dict(name, light, 48, 36, 16, integrator=integrator, twosided=False)
            imgs.append(np.array(mi.render(mi.load_dict(d))))
        same = np.array_equal(imgs[0], imgs[1])
        diff = np.abs(imgs[0] - imgs[1]).max()
        log("identity %-8s %-8s: %s (max |difference| %.3g, mean %.6g)"
            % (name, integrator, "bit-identical" if same else "DIFFERENT", diff, imgs[0].mean()))
        ok &= bool(same)
    return ok


def image_means(mi, scene, spp, seeds):
    import numpy as np
    return np.array([np.array(mi.render(scene, spp=spp, seed=s)).mean() for s in seeds])


def check_pdf(mi, scenes):
    """pdf_direction is the density sample_direction draws from, called as the integrators call
    it: sample_direction with a SurfaceInteraction3f, pdf_direction with a plain Interaction3f
    holding only p and n (what `path` keeps of the previous vertex for MIS). For every apse
    sampler, 200 seeded receivers around the plane scene's two-sided light (disk and ellipse of
    aspect 0.4) with random unit normals (every tenth zero, as in a medium) and 8 samples each:
    (1) |pdf_direction - ds.pdf| <= 1e-4 ds.pdf (the maps' float pdf(sample) agree to 1.4e-5 in
    apse's own tests; a sampler whose pdf_direction used another density, e.g. the plain map's for
    a cosine-weighted sample, is off by O(1)); (2) pdf_direction > 0 for every direction the plain
    LD-radial map samples, i.e. over the whole light (a cosine-weighted sampler whose receiver
    normal pointed away from the light would give 0 there: a biased estimator)."""
    import numpy as np
    ok = True
    for aspect in (1.0, 0.4):
        def emitter(light):
            sc = mi.load_dict(scenes.scene_dict("plane", light, 8, 8, 1, twosided=True, aspect=aspect))
            return list(sc.emitters())[0]
        plain = emitter("ld_radial")
        for light in scenes.APSE_SAMPLERS:
            em = emitter(light)
            rng = np.random.default_rng(5)
            worst, zero, pairs = 0.0, 0, 0
            for k in range(200):
                p = rng.uniform([-3, 0, -3], [3, 3, 3])
                n = rng.normal(size=3)
                n = np.zeros(3) if k % 10 == 0 else n / np.linalg.norm(n)
                si = mi.SurfaceInteraction3f()
                it = mi.Interaction3f()
                si.p = it.p = mi.Point3f(p)
                si.n = it.n = mi.Normal3f(n)
                for _ in range(8):
                    u = mi.Point2f(rng.uniform(), rng.uniform())
                    ds, _w = em.sample_direction(si, u, True)
                    q = em.pdf_direction(it, ds, True)
                    if ds.pdf > 0:
                        pairs += 1
                        worst = max(worst, abs(q - ds.pdf) / ds.pdf)
                    elif q != 0:
                        worst = float("inf")
                    dp, _w = plain.sample_direction(si, u, True)
                    zero += int(dp.pdf > 0 and not em.pdf_direction(it, dp, True) > 0)
            good = worst <= 1e-4 and zero == 0 and pairs > 0
            ok &= good
            log("pdf      %-7s %-26s %4d samples: max |pdf_direction/pdf - 1| %.1e, zero density over the "
                "light %d %s" % ("disk" if aspect == 1.0 else "ellipse", light, pairs, worst, zero,
                                 "ok" if good else "FAIL"))
    return ok


def check_unbiased(plugin_dir):
    """Each sampler's mean over K = 16 independent renders (seeds) at 16 spp against the mean of
    Mitsuba's own light over K_REF = 64 renders at the same 16 spp (the same sample count, because
    in the medium scene Mitsuba's own light gives image means that depend on the sample count by
    ~1 %, 0.1952 +- 0.0010 at 16 spp against 0.19343 +- 0.00011 at 1024 spp; apse's samplers do
    the same). All with directly visible lights hidden, so that the anti-aliasing of their bright
    silhouettes does not swamp the light-sampling noise. With s the standard deviations of the
    per-seed image means, the tolerance is Z * sqrt(s_apse^2/K + s_ref^2/K_REF): the standard
    error of the difference, estimated from the renders themselves. Z = 5: with 15 degrees of
    freedom a Student-t exceeds 5 with probability 1.6e-4, so the 49 comparisons below fail by
    chance with probability < 0.8 % -- and never intermittently, since the seeds are fixed and
    Mitsuba's scalar renders are deterministic. The tolerances come out at 0.3-3.3 % of the image
    means (printed as "rel"): a pdf_direction that is not the density sampled from, or a wrong
    MIS weight, biases the mean by more than that."""
    import numpy as np
    mi, scenes = load(plugin_dir)
    K, K_REF, Z = 16, 64, 5.0
    ok = check_pdf(mi, scenes)
    # (scene, integrator, two-sided, standalone, aspect): the standalone light is placed by
    # center/normal/radius (its samples are flagged delta: no MIS), the others attached to the
    # disk; aspect 0.4 squeezes the disk into an ellipse (sampled through project_ellipse)
    cases = (("plane", "direct", False, False, 1.0), ("plane", "path", True, False, 1.0),
             ("spheres", "path", False, False, 1.0), ("spheres", "direct", True, False, 1.0),
             ("medium", "volpath", False, False, 1.0), ("plane", "path", False, True, 1.0),
             ("plane", "path", False, False, 0.4))
    for name, integrator, twosided, standalone, aspect in cases:
        kw = dict(integrator=integrator, twosided=twosided, hide_emitters=True, aspect=aspect)
        ref_scene = mi.load_dict(scenes.scene_dict(name, "mitsuba", 32, 24, 16, **kw))
        ref = image_means(mi, ref_scene, 16, range(1000, 1000 + K_REF))
        for light in ("area",) + scenes.APSE_SAMPLERS:
            sc = mi.load_dict(scenes.scene_dict(name, light, 32, 24, 16, standalone=standalone, **kw))
            m = image_means(mi, sc, 16, range(K))
            diff = m.mean() - ref.mean()
            tol = Z * np.sqrt(m.var(ddof=1) / K + ref.var(ddof=1) / K_REF)
            good = abs(diff) <= tol
            ok &= bool(good)
            log("unbiased %-7s %-7s %-13s %-26s mean %.6f ref %.6f diff %+.2e tol %.2e (rel %.2f %%, "
                "|diff| = %.1f sigma) %s" % (name, integrator, ("2-sided" if twosided else "1-sided") + ("/alone" if standalone else "")
                                             + ("/ellipse" if aspect != 1.0 else ""), light,
                                             m.mean(), ref.mean(), diff, tol, 100 * tol / ref.mean(),
                                             Z * abs(diff) / tol, "ok" if good else "FAIL"))
    return ok


def check_relmse(plugin_dir):
    """relMSE at 16 spp (`stratified`) of each apse sampler <= 0.3x Mitsuba's own light, on the
    ground scene (one-sided light, `direct`), against Mitsuba's own light at 1024 spp (so the
    reference owes nothing to apse; its own noise only adds the same constant to both relMSEs,
    which moves the ratio towards 1, against the test)."""
    import numpy as np
    mi, scenes = load(plugin_dir)
    from compare import rel_mse
    w, h = 64, 48
    kw = dict(integrator="direct", twosided=False, hide_emitters=True)
    ref = np.array(mi.render(mi.load_dict(scenes.scene_dict("plane", "mitsuba", w, h, 1024, seed=7, **kw))))
    base = rel_mse(np.array(mi.render(mi.load_dict(scenes.scene_dict("plane", "mitsuba", w, h, 16, **kw)))), ref)
    log("relmse  plane direct 16 spp stratified: mitsuba %.3e" % base)
    ok = True
    for light in scenes.APSE_SAMPLERS:
        e = rel_mse(np.array(mi.render(mi.load_dict(scenes.scene_dict("plane", light, w, h, 16, **kw)))), ref)
        good = e <= 0.3 * base
        ok &= good
        log("relmse  %-26s %.3e = %.3f x mitsuba (limit 0.3) %s" % (light, e, e / base, "ok" if good else "FAIL"))
    return ok


# ------------------------------------------------------------------------------------------------
# The sphere light (apse_sphere) against Mitsuba's own: a sphere shape with an `area` emitter,
# which samples the cone the sphere subtends uniformly (scenes.sphere_scene_dict)

def check_sphere_identity(plugin_dir):
    """apse_sphere with sampler=area renders bit-identical images to Mitsuba's own sphere light."""
    import numpy as np
    mi, scenes = load(plugin_dir)
    ok = True
    for integrator in ("direct", "path"):
        imgs = [np.array(mi.render(mi.load_dict(scenes.sphere_scene_dict(light, 48, 36, 16, integrator=integrator))))
                for light in ("mitsuba", "area")]
        same = np.array_equal(imgs[0], imgs[1])
        log("identity sphere %-6s: %s (max |difference| %.3g, mean %.6g)"
            % (integrator, "bit-identical" if same else "DIFFERENT", np.abs(imgs[0] - imgs[1]).max(), imgs[0].mean()))
        ok &= bool(same)
    return ok


def check_sphere_pdf(mi, scenes):
    """pdf_direction is the density sample_direction draws from, for light samples and for
    BSDF-sampled directions, called as `path` calls them (sample_direction with a
    SurfaceInteraction3f; pdf_direction with a plain Interaction3f holding p and n, and, for a
    BSDF ray that hit the sphere, the DirectionSample3f the integrator builds from the hit). For
    every apse sampler, 200 seeded receivers in [-3, 3] x [0, 3] x [-3, 3] around the sphere
    light of the `sphere` scene (some inside it: no light samples, density 0), random unit normals
    (every tenth zero, as in a medium):
    (1) 8 light samples each: |pdf_direction - ds.pdf| <= 1e-4 ds.pdf (the maps' float pdf(sample)
        agree to 1.4e-5 in apse's own tests; another density is off by O(1)), and the sample's
        point on the sphere: ||p - c| - r| <= 1e-5 r (float rounding of points a few radii away
        is ~1e-6 r; a point off the sphere would make the shadow ray stop short or pass through);
    (2) 16 directions each, uniform in the cone of 1.3x the half-angle alpha of the cap around the
        sphere's centre (a BSDF lobe aimed at the light: hits right up to the silhouette and
        misses just outside it), traced against the sphere alone. Every hit from outside must
        have pdf_direction > 0 (the whole light has a density: else MIS is biased) and equal an
        independent closed form at the direction the integrator passes, within 1e-4 (float
        rounding of the cap's solid angle and of the direction at these distances is ~1e-6): for
        the uniform maps (radial, LD-radial, parallel, tabulated LD-radial) 1/Omega, Omega =
        2 pi (1 - cos alpha); for the cosine-weighted ones, where the sphere is entirely on one
        side of the receiver's plane, |n.w| / E, E = pi sin^2 alpha |n.axis| the cap's projected
        solid angle (CosineWeighted samples caps exactly in proportion to the cosine; a
        pdf_direction that gave the plain map's density is off by up to 7.5x). Directions
        more than 1e-3 rad outside the cap, and every direction from inside the sphere, must have
        density 0."""
    import numpy as np
    ok = True
    center, radius = np.array([0.0, 0.5, 0.0]), 0.8
    for light in scenes.APSE_SAMPLERS:
        cosine = light.startswith("cosine_")
        ball = scenes.sphere_scene_dict(light, 8, 8, 1)["light"]
        scene = mi.load_dict({"type": "scene", "light": ball})
        em = list(scene.emitters())[0]
        rng = np.random.default_rng(11)
        worst, off_sphere, worst_bsdf = 0.0, 0.0, 0.0
        zero, nonzero, pairs, hits, checked, misses = 0, 0, 0, 0, 0, 0
        for k in range(200):
            p = rng.uniform([-3, 0, -3], [3, 3, 3])
            n = rng.normal(size=3)
            n = np.zeros(3) if k % 10 == 0 else n / np.linalg.norm(n)
            si = mi.SurfaceInteraction3f()
            it = mi.Interaction3f()
            si.p = it.p = mi.Point3f(p)
            si.n = it.n = mi.Normal3f(n)
            dist = np.linalg.norm(center - p)
            out = dist > radius
            for _ in range(8):
                ds, _w = em.sample_direction(si, mi.Point2f(rng.uniform(), rng.uniform()), True)
                q = em.pdf_direction(it, ds, True)
                if ds.pdf > 0:
                    pairs += 1
                    worst = max(worst, abs(q - ds.pdf) / ds.pdf, 0.0 if out else float("inf"))
                    off_sphere = max(off_sphere, abs(np.linalg.norm(np.array(ds.p) - center) - radius) / radius)
                elif q != 0:
                    worst = float("inf")
            axis = (center - p) / dist
            sin_a = min(1.0, radius / dist)
            alpha = np.arcsin(sin_a) if out else np.pi
            t1 = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
            t1 /= np.linalg.norm(t1)
            t2 = np.cross(axis, t1)
            for _ in range(16):
                z = 1 - rng.uniform() * (1 - np.cos(min(np.pi, 1.3 * alpha)))
                phi = 2 * np.pi * rng.uniform()
                d = z * axis + np.sqrt(max(0.0, 1 - z * z)) * (np.cos(phi) * t1 + np.sin(phi) * t2)
                hit = scene.ray_intersect(it.spawn_ray(mi.Vector3f(d)))
                if out and hit.is_valid():
                    hits += 1
                    ds = mi.DirectionSample3f(scene, hit, it)
                    q = em.pdf_direction(it, ds, True)
                    zero += int(not q > 0)
                    w = np.array(ds.d, dtype=float)
                    w /= np.linalg.norm(w)
                    if not cosine:
                        expected = 1 / (2 * np.pi * (1 - np.sqrt(1 - sin_a ** 2)))
                    elif abs(n @ (center - p)) > radius:
                        expected = abs(n @ w) / (np.pi * sin_a ** 2 * abs(n @ axis))
                    else:
                        continue
                    checked += 1
                    worst_bsdf = max(worst_bsdf, abs(q / expected - 1))
                elif not out or np.arccos(np.clip(d @ axis, -1, 1)) > alpha + 1e-3:
                    ds = mi.DirectionSample3f()
                    ds.d = mi.Vector3f(d)
                    ds.n = mi.Normal3f(-d)
                    misses += 1
                    nonzero += int(em.pdf_direction(it, ds, True) != 0)
        good = (worst <= 1e-4 and off_sphere <= 1e-5 and worst_bsdf <= 1e-4 and zero == 0
                and nonzero == 0 and pairs > 0 and checked > 0 and misses > 0)
        ok &= good
        log("pdf      sphere %-26s %4d samples: max |pdf_direction/pdf - 1| %.1e, point off the sphere %.1e r; "
            "%4d BSDF hits: zero density %d, max |pdf/closed form - 1| %.1e over %d; off the light: density > 0 %d of %d %s"
            % (light, pairs, worst, off_sphere, hits, zero, worst_bsdf, checked, nonzero, misses,
               "ok" if good else "FAIL"))
    return ok


def check_sphere_unbiased(plugin_dir):
    """check_sphere_pdf, then every apse_sphere sampler's image mean against Mitsuba's own sphere
    light, exactly as check_unbiased does for the disk (K = 16 renders against K_REF = 64 at
    16 spp, 32 x 24 pixels, lights hidden from the camera; tolerance 5 standard errors of the
    difference, estimated from the renders: with 15 degrees of freedom a Student-t exceeds 5 with
    probability 1.6e-4, so the 21 comparisons fail by chance with probability < 0.4 %, never
    intermittently). Cases: `direct` and `path` with the light attached to its sphere (MIS with
    BSDF samples that hit it), `direct` with the standalone light (no MIS; no sphere shape, see
    scenes.sphere_scene_dict)."""
    import numpy as np
    mi, scenes = load(plugin_dir)
    K, K_REF, Z = 16, 64, 5.0
    ok = check_sphere_pdf(mi, scenes)
    for integrator, standalone in (("direct", False), ("path", False), ("direct", True)):
        kw = dict(integrator=integrator, hide_emitters=True)
        ref = image_means(mi, mi.load_dict(scenes.sphere_scene_dict("mitsuba", 32, 24, 16, **kw)), 16,
                          range(1000, 1000 + K_REF))
        for light in ("area",) + scenes.APSE_SAMPLERS:
            if standalone and light == "area":
                continue  # the area mode is the shape's own sampling: it needs the shape
            sc = mi.load_dict(scenes.sphere_scene_dict(light, 32, 24, 16, standalone=standalone, **kw))
            m = image_means(mi, sc, 16, range(K))
            diff = m.mean() - ref.mean()
            tol = Z * np.sqrt(m.var(ddof=1) / K + ref.var(ddof=1) / K_REF)
            good = abs(diff) <= tol
            ok &= bool(good)
            log("unbiased sphere %-6s %-8s %-26s mean %.6f ref %.6f diff %+.2e tol %.2e (rel %.2f %%, "
                "|diff| = %.1f sigma) %s" % (integrator, "alone" if standalone else "attached", light, m.mean(),
                                             ref.mean(), diff, tol, 100 * tol / ref.mean(), Z * abs(diff) / tol,
                                             "ok" if good else "FAIL"))
    return ok


def check_sphere_relmse(plugin_dir):
    """relMSE at 16 spp (`stratified`) and efficiency 1/(relMSE x CPU time) of every apse_sphere
    sampler against Mitsuba's own sphere light, on the `sphere` scene with `direct`, 64 x 48
    pixels, against Mitsuba's light at 1024 spp (a reference that owes nothing to apse; its noise
    adds the same constant to every relMSE, which moves the ratios towards 1, against the test).
    Mitsuba's light samples the cone uniformly in solid angle, as apse's maps do: what differs is
    how much of the `stratified` sampler's stratification each mapping of the square keeps (and,
    for the cosine_* samplers, the weighting). Printed for the whole image and for the pixels
    that see only the ground (the light straddles their horizon: the cosine_* samplers are the
    plain map there), only the wall (the light above their horizon) or neither (next to the
    sphere), told apart by the geometric normal (the `aov` integrator); --into writes the same as
    the table of docs/mitsuba3.md (sphere_relmse_table). Time: CPU time of the render, the
    smallest of 5, noisy on a shared machine: printed, never tested. Limits, from the measured ratios (whole
    image: radial 0.91, the other plain maps 0.63-0.64, the cosine-weighted ones 0.59; on the
    wall the cosine-weighted ones 0.51x the plain LD-radial map's) with room for changes of the
    maps: whole image, radial <= 1 (no worse than the cone), the other maps <= 0.75; on the wall
    the cosine-weighted samplers <= 0.7x the plain LD-radial map's relMSE."""
    import numpy as np
    mi, scenes = load(plugin_dir)
    from compare import timed_render
    load_start = os.getloadavg()[0]
    w, h = 64, 48
    kw = dict(integrator="direct", hide_emitters=True)
    ref = np.array(mi.render(mi.load_dict(scenes.sphere_scene_dict("mitsuba", w, h, 1024, seed=7, **kw))))
    aov = scenes.sphere_scene_dict("mitsuba", w, h, 16, **kw)
    aov["integrator"] = {"type": "aov", "aovs": "n:geo_normal"}
    normal = np.array(mi.render(mi.load_dict(aov)))
    regions = {"all": np.ones((h, w), bool), "ground": normal[..., 1] > 0.999, "wall": normal[..., 2] > 0.999}
    regions["other"] = ~(regions["ground"] | regions["wall"])  # next to the sphere: silhouette, ground beneath
    r = ref.mean(axis=2)
    scale = 0.01 * r.mean() ** 2

    def rel_mse(img):  # compare.rel_mse, per region (the same normalisation by the whole image)
        e = (img.mean(axis=2) - r) ** 2 / (r ** 2 + scale)
        return {k: float(e[m].mean()) for k, m in regions.items()}

    results, images = {}, {}
    for light in ("mitsuba",) + scenes.APSE_SAMPLERS:
        img, t = timed_render(mi.load_dict(scenes.sphere_scene_dict(light, w, h, 16, **kw)), 16, 0, 5)
        results[light], images[light] = (rel_mse(img), t), img
    (base, base_t), ld_wall = results["mitsuba"], results["ld_radial"][0]["wall"]
    pixels = {k: int(m.sum()) for k, m in regions.items()}
    log("relmse  sphere direct 16 spp stratified: mitsuba %.3e (ground %.3e, wall %.3e, other %.3e; %d / %d / %d "
        "pixels), %.3f s CPU" % (base["all"], base["ground"], base["wall"], base["other"], pixels["ground"],
                                 pixels["wall"], pixels["other"], base_t))
    ok = True
    for light in scenes.APSE_SAMPLERS:
        e, t = results[light]
        limit = 1.0 if light == "radial" else 0.75
        good = e["all"] <= limit * base["all"]
        line = ("relmse  sphere %-26s %.3e = %.3f x mitsuba (limit %.2f; ground %.3f x, wall %.3f x, other %.3f x)"
                % (light, e["all"], e["all"] / base["all"], limit, e["ground"] / base["ground"],
                   e["wall"] / base["wall"], e["other"] / base["other"]))
        if light.startswith("cosine_"):
            good &= e["wall"] <= 0.7 * ld_wall
            line += ", wall %.3f x ld_radial (limit 0.70)" % (e["wall"] / ld_wall)
        ok &= good
        log(line + "; time %.2f x, efficiency %.2f x mitsuba %s"
            % (t / base_t, (base["all"] * base_t) / (e["all"] * t), "ok" if good else "FAIL"))
    SECTIONS["sphere_relmse"] = sphere_relmse_table(results, images, pixels, (w, h), load_start,
                                                    os.getloadavg()[0])
    return ok


SPHERE_TITLES = {"radial": "radial", "ld_radial": "LD-radial", "parallel": "parallel",
                 "tabulated_ld_radial": "tabulated LD-radial", "cosine_ld_radial": "cosine LD-radial",
                 "cosine_tabulated_ld_radial": "cosine tabulated LD-radial"}


def sphere_relmse_table(results, images, pixels, size, load_start, load_end):
    """check_sphere_relmse's results as the markdown table of docs/mitsuba3.md, with the note that
    says what its numbers are."""
    import numpy as np
    import textwrap
    (base, base_t) = results["mitsuba"]
    title = lambda light: SPHERE_TITLES.get(light, "`%s`" % light)

    def sci(x):  # 6.78e-3, as the page writes it
        mantissa, exponent = ("%.2e" % x).split("e")
        return "%se%d" % (mantissa, int(exponent))
    rows = ["| sampler | relMSE vs Mitsuba | ground | wall | other pixels | time per render | efficiency vs Mitsuba |",
            "|---|---:|---:|---:|---:|---:|---:|",
            "| Mitsuba's sphere light (reference) | 1 (%s) | 1 (%s) | 1 (%s) | 1 (%s) | 1 (%.3g s) | 1 |"
            % (sci(base["all"]), sci(base["ground"]), sci(base["wall"]), sci(base["other"]), base_t)]
    for light, (e, t) in results.items():
        if light != "mitsuba":
            rows.append("| %s | %.3f× | %.3f× | %.3f× | %.3f× | %.2f× | %.2f× |"
                        % (title(light), e["all"] / base["all"], e["ground"] / base["ground"],
                           e["wall"] / base["wall"], e["other"] / base["other"], t / base_t,
                           (base["all"] * base_t) / (e["all"] * t)))
    ld = results["ld_radial"][0]
    share = lambda e: 100 * e["other"] * pixels["other"] / (e["all"] * pixels["all"])
    cosine = [light for light in results if light.startswith("cosine_")]
    groups = []  # samplers that render bit-identical images
    for light in results:
        for g in groups:
            if np.array_equal(images[g[0]], images[light]):
                g.append(light)
                break
        else:
            groups.append([light])
    twins = [" and ".join("%s %.2f×" % (title(l), results[l][1] / base_t) for l in g)
             for g in groups if len(g) > 1]
    note = ("One run of `sphere_relmse`. relMSE of one render at 16 spp against Mitsuba's light at "
            "1024 spp, as a ratio to Mitsuba's light at 16 spp (its relMSE in parentheses), over the "
            "whole %d × %d image and over the pixels that see only the ground (%d), only the wall (%d) "
            "and the %d others, next to the sphere (its silhouette, and the ground beneath it that the "
            "hidden light lets the camera see), which hold %.0f %% of Mitsuba's squared error and "
            "%.0f %% of LD-radial's."
            % (size[0], size[1], pixels["ground"], pixels["wall"], pixels["other"], share(base), share(ld)))
    walls = ["%.3f×" % (results[l][0]["wall"] / ld["wall"]) for l in cosine]
    if len(set(walls)) == 1:
        note += " On the wall, the cosine-weighted samplers' relMSE is %s the plain LD-radial map's." % walls[0]
    elif walls:
        note += (" On the wall, the cosine-weighted samplers' relMSE is %s the plain LD-radial map's."
                 % ", ".join("%s for %s" % (r, title(l)) for r, l in zip(walls, cosine)))
    note += (" Time per render: the CPU time (`time.process_time`) of one 16 spp render, the smallest of "
             "5, as a ratio to Mitsuba's light (its time in parentheses); efficiency = 1/(relMSE · time), "
             "the equal-time measure, as a ratio to Mitsuba's light. The times come from this one run on "
             "a shared machine (%d cores, load average %.1f when the check started, %.1f when it ended) "
             "and are noisy" % (len(os.sched_getaffinity(0)), load_start, load_end))
    note += (": samplers that render identical images timed %s." % "; ".join(twins) if twins else ".")
    note = textwrap.fill(note, 100, break_long_words=False, break_on_hyphens=False)
    return "\n".join(rows) + "\n\n" + note + "\n"


CHECKS = {"identity": check_identity, "unbiased": check_unbiased, "relmse": check_relmse,
          "sphere_identity": check_sphere_identity, "sphere_unbiased": check_sphere_unbiased,
          "sphere_relmse": check_sphere_relmse}
TABLES = {"sphere_relmse": ["sphere_relmse"]}  # check -> the sections it writes --into a page


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("command", choices=["setup"] + sorted(CHECKS))
    ap.add_argument("--dir", default=os.path.join(ROOT, "build", "mitsuba3"))
    ap.add_argument("--into", metavar="PAGE",
                    help="write the check's table into PAGE between its markers (%s)" % ", ".join(sorted(TABLES)))
    ap.add_argument("--in-venv", metavar="PLUGIN_DIR", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.into:
        if a.command not in TABLES:
            ap.error("--into: %s writes no table (checks with a table: %s)" % (a.command, ", ".join(sorted(TABLES))))
        try:
            with open(a.into) as f:
                missing = missing_markers(f.read(), TABLES[a.command])
        except OSError as e:
            sys.exit("mitsuba3: --into %s: %s" % (a.into, e.strerror))
        if missing:  # said before rendering, not after it
            sys.exit("%s: no %s markers" % (a.into, ", ".join(missing)))
    if a.in_venv:
        t0 = time.time()
        ok = CHECKS[a.command](a.in_venv)
        log("mitsuba3 %s: %s in %.1f s" % (a.command, "passed" if ok else "FAILED", time.time() - t0))
        if a.into:  # written even when a limit fails (the exit code says so), as projection_report does
            write_into(a.into, {name: SECTIONS[name] for name in TABLES[a.command]})
        sys.exit(0 if ok else 1)
    py, bdir = setup(os.path.abspath(a.dir))
    if a.command == "setup":
        log(py)
        return
    into = ["--into", os.path.abspath(a.into)] if a.into else []
    r = subprocess.run([py, os.path.abspath(__file__), a.command, "--in-venv", bdir] + into)
    sys.exit(r.returncode)


if __name__ == "__main__":
    main()
