#!/usr/bin/env python3
"""Turn a benchmark's JSON output into a markdown table. Two inputs are recognised by their
benchmark names:

* bench_elliptic: median ns per call of every apse elliptic function in float and double, of each
  peer computing the same function on the same inputs, and the ratio peer / apse (> 1: apse is
  faster).

    bench_elliptic --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \\
                   --benchmark_format=json > elliptic.json
    python3 tools/bench_table.py elliptic.json          (or: ... | python3 tools/bench_table.py)

* bench_samplers (names <sampler>/<float|double>/<samples>): the "Speed" table — one row per
  sampler, the ratio of its median time to lean area sampling's (DiskAreaSampler from the light's
  stored DiskFrame, same run) for set-up + 1 and set-up + 16 samples in double and float, the
  median ns in parentheses, and the mean iterations (or table-walk steps) and acceptance per
  sample; then the cost breakdown per map (projection, solid angle, map set-up, per sample) from
  the set-up-only runs (<sampler>/<type>/0, "projection", "projection_solid_angle"); then the
  sphere-light table (names sphere_*), whose reference is pbrt-v4's cone sampling run alongside.

    bench_samplers --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \\
                   --benchmark_min_time=0.2 --benchmark_enable_random_interleaving=true \\
                   --benchmark_format=json > samplers.json
    python3 tools/bench_table.py samplers.json

  Given several bench_samplers outputs (the same benchmark built in different code layouts,
  bench_samplers_align*; tools/speed.sh runs them), every ratio is the median over them of the
  per-run ratio, every time the median time, and a second table gives each ratio's spread
  (lowest–highest) over the layouts.

  Under the disk table the tool states the goals against lean area sampling (DISK_GOALS: the
  tabulated maps with 16 samples ≤ 2.5×, the tabulated LD-radial map's set-up + 1 ≤ 4×, the exact
  LD-radial map's ≤ 8×, the parallel map's ≤ 10×, in double and float; float at least as fast as
  double for every sampler), each with its median, spread and "met" or "not met"; then the
  tabulated LD-radial map's time against the exact one's (numerical inversion vs tabulation) and
  the fraction of samples GamitoSingleShot rejects. Every ratio there is taken within one run and
  then the median over the runs, as in the table.

  From the same outputs, the cost table of docs/cosine_weighted.md (section cosine_cost): the
  plain maps and the cosine-weighted samplers as ratios to the plain TabulatedLdRadialMap, each
  taken within one run and then the median over the runs, like the speed table's.

Uses the "median" aggregates when repetitions were run, the plain runs otherwise. The header
states the CPU and compiler recorded in the JSON context. Only the standard library is needed.

* bench_mis_query (names <query>/<hit|bsdf><float|double>): the cost of the stateless MIS
  query per map, for directions that hit the disk (docs/tabulated.md).

* bench_projection (names <function><float|double>): the per-shading-point set-up of
  docs/projection.md — lean area sampling, project_disk, solid_angle, both, their ratio to area
  sampling, and the other shapes' projections. Its console output is its own, so the JSON is
  written with --benchmark_out:

    bench_projection --benchmark_repetitions=11 --benchmark_min_time=0.1 \\
                     --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \\
                     --benchmark_out=projection.json --benchmark_out_format=json
    python3 tools/bench_table.py --into docs/projection.md projection.json

With --into PAGE the tables are written into the markdown page instead of printed: each section
(disks: the disk table, its spread and the goal verdicts; breakdown: the cost breakdown; spheres: the sphere-light
table; cosine_cost: the cosine-weighted cost table; elliptic: the elliptic-integral table;
mis_query: the MIS-query table; projection: the projection speed table) replaces what stands
between the page's lines `<!-- bench_table.py: NAME -->` and `<!-- /bench_table.py: NAME -->`, so
that a measured table lives in one place and is never copied by hand. --into may be given more
than once: each section goes to every page that has its markers, and it is an error (nothing
written) if none has them:

    python3 tools/bench_table.py --into docs/speed.md --into docs/cosine_weighted.md samplers.json
    python3 tools/bench_table.py --into docs/elliptic.md elliptic.json
    python3 tools/bench_table.py --into docs/tabulated.md mis_query.json
    python3 tools/bench_table.py --into docs/projection.md projection.json
"""

import contextlib
import io
import json
import re
import sys

SECTIONS = {}  # section name -> its markdown, when written --into a page


@contextlib.contextmanager
def section(name):
    """Collects what is printed inside into SECTIONS[name] (main prints it, or writes it --into)."""
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        yield
    SECTIONS[name] = buf.getvalue()


def markers(name, tool='bench_table.py'):
    """The lines between which a page holds the section `name` that `tool` writes."""
    return '<!-- %s: %s -->\n' % (tool, name), '<!-- /%s: %s -->' % (tool, name)


def missing_markers(text, names, tool='bench_table.py'):
    """The sections of `names` whose begin and end markers are not both in `text`, in order."""
    out = []
    for name in names:
        begin, end = markers(name, tool)
        i, j = text.find(begin), text.find(end)
        if i < 0 or j < i:
            out.append('%s ... %s' % (begin.strip(), end))
    return out


def write_into(pages, sections=None, tool='bench_table.py'):
    """Replaces each section (default: the collected SECTIONS) between its markers in every one of
    `pages` that has them (an error, with nothing written, if a section's markers are in none of
    them). Other tools (mitsuba3_test.py) write their tables with their own name in the markers."""
    sections = SECTIONS if sections is None else sections
    texts = {}
    for page in pages:
        with open(page) as f:
            texts[page] = f.read()
    written = []
    for name, body in sections.items():
        begin, end = markers(name, tool)
        found = False
        for page in pages:
            if missing_markers(texts[page], [name], tool):
                continue
            text = texts[page]
            i, j = text.find(begin), text.find(end)
            texts[page] = text[:i + len(begin)] + '\n' + body.strip('\n') + '\n\n' + text[j:]
            written.append((page, name))
            found = True
        if not found:
            sys.exit('%s: no %s ... %s markers' % (' or '.join(pages), begin.strip(), end))
    for page in pages:
        if any(p == page for p, _ in written):
            with open(page, 'w') as f:
                f.write(texts[page])
    for page, name in written:
        print('%s: section %s written' % (page, name), file=sys.stderr)

# benchmark name prefix -> column title
PEERS = [
    ('std', 'libstdc++ std::'),
    ('boost', 'Boost (default policy)'),
    ('boostnp', 'Boost (no promotion)'),
]
FUNCTIONS = [
    ('rf', 'carlson_rf'),
    ('rd', 'carlson_rd'),
    ('rj', 'carlson_rj (random args)'),
    ('rj_solid_angle', 'carlson_rj (solid angle: x = 0)'),
    ('rc', 'carlson_rc'),
    ('ellint_f', 'ellint_f'),
    ('ellint_pi', 'ellint_pi'),
    ('comp_ellint_k', 'comp_ellint_k'),
    ('comp_ellint_pi', 'comp_ellint_pi'),
]
NAME = re.compile(r'^(apsedbl|apse|std|boostnp|boost)_(\w+?)<(float|double)>$')

# bench_samplers: benchmark sampler name -> row title, in table order (area is the reference)
SAMPLERS = [
    ('area', '`DiskAreaSampler`, frame stored per light (reference)'),
    ('area_frame_per_point', '`DiskAreaSampler`, frame built per shading point'),
    ('gamito_single_shot', '`GamitoSingleShot`'),
    ('gamito_retry8', '`GamitoRetry` (N = 8)'),
    ('rectangle', '`SphericalRectangle` (bounding square)'),
    ('radial', '`RadialMap`'),
    ('ld_radial', '`LdRadialMap`'),
    ('parallel', '`ParallelMap`'),
    ('tabulated', '`TabulatedMap`'),
    ('tabulated_ld_radial', '`TabulatedLdRadialMap`'),
    ('cosine_radial', '`CosineWeighted<RadialMap>`'),
    ('cosine_ld_radial', '`CosineWeighted<LdRadialMap>`'),
    ('cosine_parallel', '`CosineWeighted<ParallelMap>`'),
    ('cosine_tabulated', '`CosineWeighted<TabulatedMap>`'),
    ('cosine_tabulated_ld_radial', '`CosineWeighted<TabulatedLdRadialMap>`'),
    ('cosine_tabulated_ld_radial_16_nodes', '`CosineWeighted<TabulatedLdRadialMap, 16>`'),
    ('cosine_tabulated_ld_radial_32_nodes', '`CosineWeighted<TabulatedLdRadialMap, 32>`'),
]
# bench_samplers' sphere-light rows (names sphere_*), in table order; each row's reference is
# pbrt-v4's cone sampling (sphere_cone), the SphereLight rows' the same with the point on the
# sphere (sphere_cone_point)
SPHERES = [
    ('sphere_cone', 'pbrt-v4 cone sampling, direction (reference)'),
    ('sphere_cone_point', 'pbrt-v4 cone sampling + point and distance (reference of the `SphereLight` rows)'),
    ('sphere_radial', '`RadialMap`'),
    ('sphere_ld_radial', '`LdRadialMap`'),
    ('sphere_parallel', '`ParallelMap`'),
    ('sphere_tabulated', '`TabulatedMap`'),
    ('sphere_tabulated_ld_radial', '`TabulatedLdRadialMap`'),
    ('sphere_cap_radial', '`RadialMap::CapSampler` (what `SphereLight<RadialMap>` holds)'),
    ('sphere_cap_ld_radial', '`LdRadialMap::CapSampler`'),
    ('sphere_cap_tabulated', '`TabulatedMap::CapSampler`'),
    ('sphere_cap_tabulated_ld_radial', '`TabulatedLdRadialMap::CapSampler`'),
    ('sphere_light_radial', '`SphereLight<RadialMap>`'),
    ('sphere_light_ld_radial', '`SphereLight<LdRadialMap>`'),
    ('sphere_light_parallel', '`SphereLight<ParallelMap>`'),
    ('sphere_light_tabulated', '`SphereLight<TabulatedMap>`'),
    ('sphere_light_tabulated_ld_radial', '`SphereLight<TabulatedLdRadialMap>`'),
    ('sphere_light_cosine_ld_radial_above', '`SphereLight<CosineWeighted<LdRadialMap>>`, cap above the horizon'),
    ('sphere_light_cosine_ld_radial_cut', '`SphereLight<CosineWeighted<LdRadialMap>>`, cap cut by the horizon'),
    ('sphere_light_cosine_tabulated_ld_radial_above',
     '`SphereLight<CosineWeighted<TabulatedLdRadialMap>>`, cap above the horizon'),
    ('sphere_light_cosine_tabulated_ld_radial_cut',
     '`SphereLight<CosineWeighted<TabulatedLdRadialMap>>`, cap cut by the horizon'),
    ('sphere_cosine_ld_radial_above', '`CosineWeighted<LdRadialMap>`, cap above the horizon'),
    ('sphere_cosine_ld_radial_cut', '`CosineWeighted<LdRadialMap>`, cap cut by the horizon'),
    ('sphere_cosine_tabulated_ld_radial_above', '`CosineWeighted<TabulatedLdRadialMap>`, cap above the horizon'),
    ('sphere_cosine_tabulated_ld_radial_cut', '`CosineWeighted<TabulatedLdRadialMap>`, cap cut by the horizon'),
    ('sphere_cosine_parallel_above', '`CosineWeighted<ParallelMap>`, cap above the horizon'),
    ('sphere_cosine_parallel_cut', '`CosineWeighted<ParallelMap>`, cap cut by the horizon'),
]
# docs/cosine_weighted.md's cost table (section cosine_cost): benchmark sampler name -> row title,
# in table order; every ratio is to COSINE_COST_REFERENCE in the same run, and the reference and
# COSINE_COST_BOLD (the default warp, in bold) show their median ns
COSINE_COST_REFERENCE = 'tabulated_ld_radial'
COSINE_COST_BOLD = 'cosine_tabulated_ld_radial'
COSINE_COST = [
    ('tabulated_ld_radial', '`TabulatedLdRadialMap` (reference)'),
    ('tabulated', '`TabulatedMap`'),
    ('ld_radial', '`LdRadialMap`'),
    ('radial', '`RadialMap`'),
    ('parallel', '`ParallelMap`'),
    ('cosine_radial', '`CosineWeighted<RadialMap>` (exact sampler)'),
    ('cosine_ld_radial', '`CosineWeighted<LdRadialMap>` (exact sampler)'),
    ('cosine_parallel', '`CosineWeighted<ParallelMap>` (exact sampler)'),
    ('cosine_tabulated', '`CosineWeighted<TabulatedMap>` (warp)'),
    ('cosine_tabulated_ld_radial', '**`CosineWeighted<TabulatedLdRadialMap>` (warp)**'),
    ('cosine_tabulated_ld_radial_16_nodes', 'the same, 16 nodes'),
    ('cosine_tabulated_ld_radial_32_nodes', 'the same, 32 nodes'),
]
# the goals against lean area sampling printed under the disk table: (title, [(sampler, samples)],
# the largest ratio that meets the goal), each checked in double and in float on the median over
# the runs of the ratio measured within one run (the table's ratio); and float at least as fast as
# double for every sampler (float time / double time within one run, the median over the runs, <= 1)
DISK_GOALS = [
    ('`TabulatedMap` and `TabulatedLdRadialMap`, set-up + 16', [('tabulated', 16), ('tabulated_ld_radial', 16)], 2.5),
    ('`TabulatedLdRadialMap`, set-up + 1', [('tabulated_ld_radial', 1)], 4.0),
    ('`LdRadialMap` (exact), set-up + 1', [('ld_radial', 1)], 8.0),
    ('`ParallelMap`, set-up + 1', [('parallel', 1)], 10.0),
]
# numerical inversion vs tabulation: this sampler's time / that one's, within one run
INVERSION = ('tabulated_ld_radial', 'ld_radial')
# the sampler whose rejected fraction (1 − accepted) is stated under the disk table
REJECTING = 'gamito_single_shot'
# set-up parts (cost breakdown only)
PARTS = [('projection', 'project_disk'), ('projection_solid_angle', 'project_disk + solid_angle')]
# maps in the cost breakdown, and whether their set-up computes the solid angle
BREAKDOWN = [('radial', True), ('ld_radial', True), ('parallel', True), ('tabulated', False),
             ('tabulated_ld_radial', False), ('cosine_tabulated', False), ('cosine_tabulated_ld_radial', False)]
SAMPLER_NAME = re.compile(r'^(\w+)/(float|double)/(\d+)$')


def selected_runs(data):
    """The median aggregates if repetitions were run, else the plain runs; and which it was."""
    runs = data.get('benchmarks', [])
    have_median = any(b.get('aggregate_name') == 'median' for b in runs)
    out = []
    for b in runs:
        if have_median and b.get('aggregate_name') != 'median':
            continue
        if not have_median and b.get('run_type') == 'aggregate':
            continue
        out.append(b)
    return out, have_median


def ns(b):
    return b['cpu_time'] * {'ns': 1.0, 'us': 1e3, 'ms': 1e6, 's': 1e9}[b.get('time_unit', 'ns')]


def header(ctx, have_median, repetitions, extra=''):
    return '%s (%s CPUs, %s MHz), %s; assertions %s%s; %s.' % (
        ctx.get('cpu_model', 'unknown CPU'), ctx.get('num_cpus', '?'), ctx.get('mhz_per_cpu', '?'),
        ctx.get('compiler', 'unknown compiler'), ctx.get('apse_assertions', '?'), extra,
        ('median CPU time of %s repetitions' % repetitions) if have_median
        else 'CPU time of one run')


def sampler_runs(data):
    """{(sampler, type, samples): run} of one bench_samplers output, and its repetitions."""
    runs, have_median = selected_runs(data)
    res = {}
    reps = '?'
    for b in runs:
        m = SAMPLER_NAME.match(b.get('run_name', b['name']))
        if m:
            res[(m.group(1), m.group(2), int(m.group(3)))] = b
            reps = b.get('repetitions', reps)
    return res, have_median, reps


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def layout_name(data):
    exe = data.get('context', {}).get('executable', '')
    m = re.search(r'_align(\d+)$', exe)
    return ('functions aligned to %s bytes' % m.group(1)) if m else 'default layout'


def reference_of(sampler):
    """The row a sampler's ratio is taken to: area sampling for disks, cone sampling for spheres."""
    if sampler.startswith('sphere_light_'):
        return 'sphere_cone_point'
    return 'sphere_cone' if sampler.startswith('sphere_') else 'area'


def layout_ratios(layouts, keys, reference):
    """Per key (sampler, type, samples): the median time over the runs (`layouts`, from
    sampler_runs), and the list of per-run ratios of its time to that of the key reference(key)
    (each ratio taken within one run; keys with no run holding both get none). Every table of
    ratios shows the median of these lists."""
    times, ratios = {}, {}
    for key in keys:
        t = [ns(r[key]) for r, _, _ in layouts if key in r]
        times[key] = median(t)
        ref = reference(key)
        q = [ns(r[key]) / ns(r[ref]) for r, _, _ in layouts if key in r and ref in r]
        if q:
            ratios[key] = q
    return times, ratios


def samplers_table(datas):
    layouts = [sampler_runs(d) for d in datas]
    have_median, reps = layouts[0][1], layouts[0][2]
    keys = set().union(*(set(r) for r, _, _ in layouts))
    # per key: the median time over the layouts, and the per-layout ratios to the reference
    times, ratios = layout_ratios(layouts, keys, lambda key: (reference_of(key[0]),) + key[1:])
    extra = ''
    if len(datas) > 1:
        extra = '; median over %d code layouts (%s)' % (len(datas), ', '.join(layout_name(d) for d in datas))
    head = header(datas[0].get('context', {}), have_median, reps, extra)
    disk_keys = {k for k in keys if not k[0].startswith('sphere_')}
    sphere_keys = keys - disk_keys

    def titled_table(name, section_keys, titles, note):
        with section(name):
            print(head)
            print()
            ratio_table(layouts, section_keys, times, ratios, titles, len(datas), note)

    if disk_keys:
        titled_table('disks', disk_keys, SAMPLERS,
                     'Per fresh shading point: set-up (projection + map, or the baseline\'s own) + 1 or 16 '
                     'samples, 1024 seeded unit disks 0.1–1000 radii away (log-uniform), all orientations, '
                     'the same points of the square for every sampler. Ratio = median time / median time of '
                     'DiskAreaSampler in the same run (> 1: slower than area sampling)')
        with section('disks'):
            print(SECTIONS['disks'], end='')
            disk_verdicts(layouts, disk_keys, ratios, len(datas))
        with section('breakdown'):
            breakdown_table(times, ratios)
    if sphere_keys:
        titled_table('spheres', sphere_keys, SPHERES,
                     'Sphere lights, per fresh shading point: set-up (project_sphere + map; the cone '
                     'sampler\'s own) + 1 or 16 samples, 1024 seeded unit spheres 1.05–50 radii away '
                     '(log-uniform); the cosine-weighted rows for receivers that see the cap above their '
                     'horizon or cut by it. Ratio = median time / median time of pbrt-v4\'s cone sampling '
                     'in the same run (the SphereLight rows: of cone sampling with the point and distance; '
                     '> 1: slower)')
    cosine_keys = {k for k in keys if k[0] in dict(COSINE_COST) and k[2] > 0}
    if (any(k[0] == COSINE_COST_REFERENCE for k in cosine_keys) and
            any(k[0].startswith('cosine_') for k in cosine_keys)):
        with section('cosine_cost'):
            print(head)
            print()
            cosine_cost_table(layouts, cosine_keys, len(datas))


def cosine_cost_table(layouts, keys, n_layouts):
    """docs/cosine_weighted.md's cost table: each row's ratio to COSINE_COST_REFERENCE (per run, then
    the median over the runs, as in the speed table)."""
    times, ratios = layout_ratios(layouts, keys, lambda key: (COSINE_COST_REFERENCE,) + key[1:])
    cols = [('double', 1), ('double', 16), ('float', 1), ('float', 16)]

    def cell(key, ty, n):
        if (key, ty, n) not in times:
            return '—'
        if key == COSINE_COST_REFERENCE:
            return '1 (%.0f ns)' % times[(key, ty, n)]
        if (key, ty, n) not in ratios:
            return '%.0f ns' % times[(key, ty, n)]
        q = median(ratios[(key, ty, n)])
        if key == COSINE_COST_BOLD:
            return '**%.2f×** (%.0f ns)' % (q, times[(key, ty, n)])
        return '%.2f×' % q

    print('| sampler | ' + ' | '.join('%s, set-up + %d' % c for c in cols) + ' |')
    print('|---|' + '---:|' * len(cols))
    for key, title in COSINE_COST:
        if any(k[0] == key for k in keys):
            print('| ' + ' | '.join([title] + [cell(key, ty, n) for ty, n in cols]) + ' |')
    print()
    print('Set-up + 1 or 16 samples per fresh shading point, the lights and receivers of the speed '
          'table. Ratio = median time / median time of `TabulatedLdRadialMap` in the same run' +
          (', then the median of that ratio over the %d runs' % n_layouts if n_layouts > 1 else '') +
          ' (> 1: slower than the plain tabulated LD-radial map); ns: median time' +
          (' over the runs.' if n_layouts > 1 else '.'))


def counter_values(first, key, name):
    """A sampler's counter `name` (mean_iterations, accepted) in (double, float) from one run
    (`first`, from sampler_runs): of the set-up + 16 run, else of the set-up + 1 run; None where
    absent."""
    vals = []
    for ty in ('double', 'float'):
        b = first.get((key, ty, 16)) or first.get((key, ty, 1))
        vals.append(b[name] if b is not None and name in b else None)
    return vals


def spread(q):
    """The spread of the per-run ratios `q` (lowest–highest), as the spread table writes it."""
    return '%.1f–%.1f×' % (min(q), max(q))


def ratio_table(layouts, keys, times, ratios, titles, n_layouts, note):
    """One table of ratios (to each row's reference_of) for the benchmark keys `keys`."""
    first = layouts[0][0]
    cols = [('double', 1), ('double', 16), ('float', 1), ('float', 16)]
    known = [k for k, _ in titles] + [k for k, _ in PARTS]
    rows = titles + [(k, '`%s`' % k) for k in sorted({key[0] for key in keys}) if k not in known]
    rows = [(k, t) for k, t in rows if any(key[0] == k and key[2] > 0 for key in keys)]
    references = {reference_of(k) for k, _ in rows}

    def cell(key, ty, n):
        if (key, ty, n) not in times:
            return '—'
        if key in references:
            return '1 (%.0f ns)' % times[(key, ty, n)]
        if (key, ty, n) not in ratios:
            return '%.0f ns' % times[(key, ty, n)]
        return '%.1f× (%.0f ns)' % (median(ratios[(key, ty, n)]), times[(key, ty, n)])

    print('| sampler | ' + ' | '.join('%s, set-up + %d' % c for c in cols) +
          ' | iterations / sample (double, float) | accepted (double, float) |')
    print('|---|' + '---:|' * (len(cols) + 2))
    for key, title in rows:
        cells = [title] + [cell(key, ty, n) for ty, n in cols]

        def counter(name, fmt):
            vals = [fmt % v if v is not None else None for v in counter_values(first, key, name)]
            return '—' if all(v is None for v in vals) else ', '.join(v or '—' for v in vals)
        cells.append(counter('mean_iterations', '%.3g'))
        cells.append(counter('accepted', '%.3g'))
        print('| ' + ' | '.join(cells) + ' |')
    print()
    print(note + (', then the median of that ratio over the layouts' if n_layouts > 1 else '') +
          '; iterations = inversion iterations (exact maps) or table-walk steps (tabulated) per '
          'sample, from the set-up + 16 runs; accepted = fraction of samples with pdf > 0.')
    if n_layouts > 1:
        print()
        print('Spread of each ratio over the %d layouts (lowest–highest):' % n_layouts)
        print()
        print('| sampler | ' + ' | '.join('%s, set-up + %d' % c for c in cols) + ' |')
        print('|---|' + '---:|' * len(cols))
        for key, title in rows:
            if key in references:
                continue
            cells = [title]
            for ty, n in cols:
                q = ratios.get((key, ty, n))
                cells.append('—' if not q else spread(q))
            print('| ' + ' | '.join(cells) + ' |')


def disk_verdicts(layouts, keys, ratios, n_layouts):
    """Under the disk table: the goals of DISK_GOALS and float against double, each with its median
    over the runs, its spread and whether it is met; the cost of tabulation against numerical
    inversion (INVERSION); the fraction REJECTING rejects. Every ratio is taken within one run
    (layout_ratios), as the table's."""
    types = ('double', 'float')
    several = n_layouts > 1

    def value(q, unit='×'):
        """The median of the per-run ratios `q`, and their spread when there are several runs."""
        if not several:
            return '%.2f%s' % (median(q), unit)
        return '%.2f%s (%.2f–%.2f%s)' % (median(q), unit, min(q), max(q), unit)

    def verdict(met):
        """'met' / '**not met**' for {type: met}, or which types meet it."""
        if all(met.values()):
            return 'met'
        if not any(met.values()):
            return '**not met**'
        return '; '.join(('met in %s' if met[ty] else '**not met** in %s') % ty for ty in types if ty in met)

    print()
    print('Goals against the lean reference, written by `tools/bench_table.py` from the runs above: '
          + ('each the median over the %d runs of the ratio measured within one run (the table\'s), '
             'its spread over the runs in parentheses:' % n_layouts if several else
             'each the ratio of the table (one run):'))
    print()
    for title, members, goal in DISK_GOALS:
        entries = [(s, ty, n) for s, n in members for ty in types if (s, ty, n) in ratios]
        if not entries:
            continue
        met = {ty: all(median(ratios[k]) <= goal for k in entries if k[1] == ty)
               for ty in types if any(k[1] == ty for k in entries)}
        parts = []
        for s, n in members:
            vals = ['%s in %s' % (value(ratios[(s, ty, n)]), ty) for ty in types if (s, ty, n) in ratios]
            if vals:
                parts.append((dict(SAMPLERS)[s] + ' ' if len(members) > 1 else '') + ', '.join(vals))
        print('* %s ≤ %g×: %s — %s.' % (title, goal, verdict(met), '; '.join(parts)))
    # float against double: each float key's time over the double key's, within one run
    fd_keys = {k for k in keys if k[1] == 'float' and k[2] > 0 and (k[0], 'double', k[2]) in keys}
    _, fd = layout_ratios(layouts, fd_keys, lambda key: (key[0], 'double', key[2]))
    if fd:
        samplers = sorted({k[0] for k in fd})
        per_n = []
        for n in sorted({k[2] for k in fd}):
            meds = [(median(q), k[0]) for k, q in fd.items() if k[2] == n]
            worst = max(meds)
            per_n.append('set-up + %d %.2f–%.2f, the highest %s %s' % (
                n, min(meds)[0], worst[0], dict(SAMPLERS).get(worst[1], '`%s`' % worst[1]),
                value(fd[(worst[1], 'float', n)], '')))
        slower = sorted((k[2], k[0]) for k, q in fd.items() if median(q) > 1)
        print('* float at least as fast as double (float time / double time per sampler %s; over the %d '
              'samplers): %s — %s%s.' % (
                  'within each run, the median over the runs' if several else 'in the run',
                  len(samplers), 'met' if not slower else '**not met**', '; '.join(per_n),
                  '' if not slower else '; above 1: ' + ', '.join(
                      '%s set-up + %d' % (dict(SAMPLERS).get(s, '`%s`' % s), n) for n, s in slower)))
    # numerical inversion against tabulation: the tabulated map's time over the exact map's
    tab, exact = INVERSION
    inv_keys = {k for k in keys if k[0] == tab and k[2] > 0 and (exact,) + k[1:] in keys}
    _, inv = layout_ratios(layouts, inv_keys, lambda key: (exact,) + key[1:])
    if inv:
        cases = []
        for n in sorted({k[2] for k in inv}):
            vals = ['%s in %s' % (value(inv[(tab, ty, n)]), ty) for ty in types if (tab, ty, n) in inv]
            cases.append('with %s per shading point %s' % ('one sample' if n == 1 else '%d samples' % n,
                                                           ' and '.join(vals)))
        print()
        print('Numerical inversion vs tabulation: %s\'s time / %s\'s %s: %s.' % (
            dict(SAMPLERS)[tab], dict(SAMPLERS)[exact],
            'within each run (median over the runs, spread in parentheses)' if several else 'in the run',
            '; '.join(cases)))
    accepted = counter_values(layouts[0][0], REJECTING, 'accepted')
    if any(a is not None for a in accepted):
        print()
        rejected = ['%.0f %%' % (100 * (1 - a)) if a is not None else None for a in accepted]
        if rejected[0] == rejected[1]:
            which = '%s of its samples in double and in float' % rejected[0]
        else:
            which = '%s of its samples' % ' and '.join('%s in %s' % (r, ty) for r, ty in zip(rejected, types) if r)
        print('%s rejects %s (1 − the accepted column).' % (dict(SAMPLERS)[REJECTING], which))


def breakdown_table(times, ratios):
    """Cost breakdown per map from the set-up-only runs (ns: median times; the last column is the
    sampler table's ratio)."""
    def t(key, ty, n):
        return times.get((key, ty, n))
    if t('projection', 'double', 0) is None:
        return
    print()
    print('| map | type | projection | solid angle | map set-up (without projection and solid angle) '
          '| per sample | set-up + 1 (measured) | set-up + 1 / area |')
    print('|---|---|---:|---:|---:|---:|---:|---:|')
    for key, has_omega in BREAKDOWN:
        title = dict(SAMPLERS).get(key, key)
        for ty in ('double', 'float'):
            proj, proj_om = t('projection', ty, 0), t('projection_solid_angle', ty, 0)
            setup, one, sixteen = t(key, ty, 0), t(key, ty, 1), t(key, ty, 16)
            if None in (proj, proj_om, setup, one, sixteen):
                continue
            omega = proj_om - proj if has_omega else 0.0
            cells = [title, ty, '%.0f' % proj, ('%.0f' % omega) if has_omega else '—',
                     '%.0f' % (setup - proj - omega), '%.1f' % ((sixteen - one) / 15), '%.0f' % one,
                     ('%.1f×' % median(ratios[(key, ty, 1)])) if (key, ty, 1) in ratios else '—']
            print('| ' + ' | '.join(cells) + ' |')
    print()
    print('ns, median times (over the layouts, if several). projection = project_disk alone (the '
          'whole ellipse kept); solid angle = (project_disk + solid_angle) − project_disk (only the exact maps compute '
          'it); map set-up = set-up alone (every field of the map kept) − the two before; per sample '
          '= (set-up + 16 − set-up + 1)/15. The parts are differences of medians, so they are '
          'accurate to a few ns.')


def load(data):
    runs = data.get('benchmarks', [])
    have_median = any(b.get('aggregate_name') == 'median' for b in runs)
    times = {}
    for b in runs:
        if have_median and b.get('aggregate_name') != 'median':
            continue
        if not have_median and b.get('run_type') == 'aggregate':
            continue
        m = NAME.match(b.get('run_name', b['name']))
        if not m:
            continue
        scale = {'ns': 1.0, 'us': 1e3, 'ms': 1e6, 's': 1e9}[b.get('time_unit', 'ns')]
        times[(m.group(1), m.group(2), m.group(3))] = b['cpu_time'] * scale
    return data.get('context', {}), times, have_median


def main():
    args = sys.argv[1:]
    pages = []
    while args[:1] == ['--into']:
        if len(args) < 2:
            sys.exit('usage: bench_table.py [--into PAGE]... [JSON...]')
        pages.append(args[1])
        args = args[2:]
    datas = [json.load(open(f)) for f in args] or [json.load(sys.stdin)]
    tables(datas)
    if pages:
        write_into(pages)
    else:
        print('\n\n'.join(body.strip('\n') for body in SECTIONS.values()))


MIS_NAME = re.compile(r'^([a-z_+]+)/(hit|bsdf)<(float|double)>$')
MIS_ROWS = [
    ('area_pdf', "area sampling's pdf (`DiskAreaSampler` from a stored frame: a ray-disk intersection)"),
    ('project_disk+contains', '`project_disk` + `contains` (the floor of every query; also the cost of a miss)'),
    ('disk_light_pdf_exact', '`disk_light_pdf<LdRadialMap>` (+ the exact map\'s set-up: one R_J and its area constants)'),
    ('disk_light_pdf_tabulated', '`disk_light_pdf<TabulatedLdRadialMap>` (+ the map\'s set-up and one look-up: '
     'an `atan2`, two blended CDF entries)'),
    ('disk_light_pdf_cosine_tabulated', '`disk_light_pdf<CosineWeighted<TabulatedLdRadialMap>>` (+ the warp\'s '
     'set-up and its density: the receiver faces the disk\'s plane, so the light\'s centre is above its '
     'horizon and the warp serves the query)'),
]


def mis_query_table(data):
    """bench_mis_query: median ns per query of each stateless pdf, for directions that hit the disk."""
    runs = data.get('benchmarks', [])
    have_median = any(b.get('aggregate_name') == 'median' for b in runs)
    times = {}
    for b in runs:
        if (b.get('aggregate_name') != 'median') if have_median else b.get('run_type') == 'aggregate':
            continue
        m = MIS_NAME.match(b.get('run_name', b['name']))
        if m:
            scale = {'ns': 1.0, 'us': 1e3, 'ms': 1e6, 's': 1e9}[b.get('time_unit', 'ns')]
            times[(m.group(1), m.group(2), m.group(3))] = b['cpu_time'] * scale
    reps = max([b.get('repetitions', 1) for b in runs] or [1])
    print(header(data.get('context', {}), have_median, reps))
    print()
    print('| query | float ns | double ns |')
    print('|---|---:|---:|')
    for key, title in MIS_ROWS:
        cells = ['%.0f' % times[(key, 'hit', ty)] if (key, 'hit', ty) in times else '—' for ty in ('float', 'double')]
        print('| %s | %s |' % (title, ' | '.join(cells)))
    tab, exact = 'disk_light_pdf_tabulated', 'disk_light_pdf_exact'
    ratios = ['%.1f' % (times[(tab, 'hit', ty)] / times[(exact, 'hit', ty)]) for ty in ('float', 'double')
              if (tab, 'hit', ty) in times and (exact, 'hit', ty) in times]
    print()
    print('Per direction that hits the disk (the costly case). The tabulated query costs %s× the exact '
          "map's (float, double)." % ' and '.join(ratios))


PROJECTION_NAME = re.compile(r'^(area_sample|project_disk|solid_angle|project_disk\+solid_angle|'
                             r'project_(?:ellipse|sphere|ellipsoid)\+solid_angle)<(float|double)>$')
PROJECTION_ROWS = [
    ('area_sample', 'lean area sampling (sampler from the stored frame, one concentric sample + solid-angle pdf)'),
    ('project_disk', '`project_disk` (stored frame)'),
    ('solid_angle', "`solid_angle` (Bulirsch's transformation from the stored cosines)"),
    ('project_disk+solid_angle', '`project_disk` + `solid_angle`'),
    (None, 'ratio to lean area sampling (CPU time)'),
    ('project_ellipse+solid_angle', '`project_ellipse` + `solid_angle`'),
    ('project_sphere+solid_angle', '`project_sphere` + `solid_angle`'),
    ('project_ellipsoid+solid_angle', '`project_ellipsoid` + `solid_angle`'),
]
PROJECTION_GOAL = 2.0  # (project_disk + solid_angle) / lean area sampling, in double


def projection_table(data):
    """bench_projection: median ns per shading point of each set-up step, and the ratio
    (project_disk + solid_angle) / lean area sampling."""
    runs, have_median = selected_runs(data)
    times = {}
    for b in runs:
        m = PROJECTION_NAME.match(b.get('run_name', b['name']))
        if m:
            times[(m.group(1), m.group(2))] = ns(b)
    reps = max([b.get('repetitions', 1) for b in runs] or [1])
    print(header(data.get('context', {}), have_median, reps))
    print()
    print('| | float | double |')
    print('|---|---:|---:|')
    ratios = {}
    for ty in ('float', 'double'):
        area, both = times.get(('area_sample', ty)), times.get(('project_disk+solid_angle', ty))
        if area and both:
            ratios[ty] = both / area
    for key, title in PROJECTION_ROWS:
        if key is None:
            cells = ['**%.2f**' % ratios[ty] if ty in ratios else '—' for ty in ('float', 'double')]
        else:
            cells = [('%.1f ns' if times[(key, ty)] < 100 else '%.0f ns') % times[(key, ty)]
                     if (key, ty) in times else '—' for ty in ('float', 'double')]
        print('| %s | %s |' % (title, ' | '.join(cells)))
    print()
    goal = ''
    if 'double' in ratios:
        goal = (' The goal, ≤ %g in double, is %s in this run.' %
                (PROJECTION_GOAL, 'met' if ratios['double'] <= PROJECTION_GOAL else '**not met**'))
    print('ns per shading point. Ratio = (`project_disk` + `solid_angle`) / lean area sampling, both '
          'from the same run.' + goal)


def tables(datas):
    data = datas[0]
    names = [b.get('run_name', b['name']) for b in data.get('benchmarks', [])]
    if any(SAMPLER_NAME.match(n) for n in names):
        samplers_table(datas)
        return
    if any(MIS_NAME.match(n) for n in names):
        with section('mis_query'):
            mis_query_table(data)
        return
    if any(PROJECTION_NAME.match(n) for n in names):
        with section('projection'):
            projection_table(data)
        return
    with section('elliptic'):
        elliptic_table(data)


def elliptic_table(data):
    ctx, times, have_median = load(data)
    cpu = ctx.get('cpu_model', 'unknown CPU')
    print('%s (%s CPUs, %s MHz), %s; %s; Boost %s; %s of %s.' % (
        cpu, ctx.get('num_cpus', '?'), ctx.get('mhz_per_cpu', '?'),
        ctx.get('compiler', 'unknown compiler'), 'assertions ' + ctx.get('apse_assertions', '?'),
        ctx.get('boost_version', 'n/a'),
        'median CPU time' if have_median else 'CPU time', 'repetitions' if have_median else 'one run'))
    print()
    peers = [(k, t) for k, t in PEERS if any(key[0] == k for key in times)]
    promoted = any(key[0] == 'apsedbl' for key in times)
    head = ['function', 'type', 'apse ns'] + (['apse, float via double ns'] if promoted else []) + \
        ['%s ns (ratio)' % t for _, t in peers]
    print('| ' + ' | '.join(head) + ' |')
    print('|' + '---|' * 2 + '---:|' * (1 + promoted + len(peers)))
    for fkey, ftitle in FUNCTIONS:
        for ty in ('float', 'double'):
            apse_t = times.get(('apse', fkey, ty))
            if apse_t is None:
                continue
            cells = [ftitle, ty, '%.1f' % apse_t]
            if promoted:
                t = times.get(('apsedbl', fkey, ty))
                cells.append('—' if t is None else '%.1f' % t)
            for pkey, _ in peers:
                t = times.get((pkey, fkey, ty))
                cells.append('—' if t is None else '%.1f (%.2fx)' % (t, t / apse_t))
            print('| ' + ' | '.join(cells) + ' |')
    print()
    print('ratio = peer time / apse time (> 1: apse is faster). Peers compute the same function on '
          'the same inputs (modulus k = sqrt(m) for std:: and Boost).' +
          (' "float via double": the float arguments converted to double, computed by apse in '
           'double and rounded back (the alternative to native float).' if promoted else ''))


if __name__ == '__main__':
    main()
