#!/usr/bin/env python3
"""Checks that include/apse/detail/ is a leaf layer (standard library only; < 1 s).

    python3 tools/check_detail_leaf.py     # exit status 1 on a violation (run by ctest: detail_is_leaf)

A header in include/apse/detail/ may include standard and third-party headers (`<...>`), other
detail headers and `../config.hpp`, nothing else: internals never depend on the public headers
(map internals that need public types live beside the maps, in include/apse/maps/).
"""

import os
import re
import sys


def violations(detail_dir):
    """(header, included path) for every quoted include of a detail header that leaves detail/
    (other than ../config.hpp) or names a file that does not exist."""
    bad = []
    for name in sorted(os.listdir(detail_dir)):
        if not name.endswith('.hpp'):
            continue
        with open(os.path.join(detail_dir, name), encoding='utf-8') as f:
            for included in re.findall(r'^\s*#\s*include\s+"([^"]+)"', f.read(), re.M):
                target = os.path.normpath(os.path.join(detail_dir, included))
                inside = os.path.dirname(target) == os.path.normpath(detail_dir)
                allowed = inside or included == '../config.hpp'
                if not allowed or not os.path.isfile(target):
                    bad.append((name, included))
    return bad


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
    detail_dir = os.path.join(root, 'include', 'apse', 'detail')
    bad = violations(detail_dir)
    for name, included in bad:
        print(f'include/apse/detail/{name}: includes "{included}" (detail/ may include only detail/ '
              f'headers and ../config.hpp)')
    if bad:
        return 1
    print(f'include/apse/detail/: a leaf layer ({len(os.listdir(detail_dir))} headers)')
    return 0


if __name__ == '__main__':
    sys.exit(main())
