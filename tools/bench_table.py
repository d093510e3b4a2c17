#!/usr/bin/env python3
"""Turn bench_elliptic's JSON output into a markdown table: median ns per call of every apse
elliptic function in float and double, of each peer computing the same function on the same
inputs, and the ratio peer / apse (> 1: apse is faster).

    bench_elliptic --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \\
                   --benchmark_format=json > elliptic.json
    python3 tools/bench_table.py elliptic.json          (or: ... | python3 tools/bench_table.py)

Uses the "median" aggregates when repetitions were run, the plain runs otherwise. The header
states the CPU and compiler recorded in the JSON context. Only the standard library is needed.
"""

import json
import re
import sys

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


def load(stream):
    data = json.load(stream)
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
    stream = open(sys.argv[1]) if len(sys.argv) > 1 else sys.stdin
    ctx, times, have_median = load(stream)
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
