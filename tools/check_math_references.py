#!/usr/bin/env python3
"""Checks that docs/math.md names only things that exist (standard library only; < 1 s).

    python3 tools/check_math_references.py     # exit status 1 if something is missing

In the "Implemented in" / "Tested by" paragraphs of docs/math.md: every quoted path must be a file,
every `symbol` after a header or source path must occur as a word in that file, and every
"test case name" after a test file must be a quoted string (the TEST_CASE name) in that file.
Run it after moving or renaming headers, functions or test cases.
"""

import os
import re
import sys


def check_references():
    """Every path, symbol and test case named in the "Implemented in" / "Tested by" paragraphs of
    docs/math.md exists: paths as files, symbols as words of the file named before them, test
    cases as quoted names in the test file named before them."""
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
    text = open(os.path.join(root, 'docs', 'math.md'), encoding='utf-8').read()
    missing = []
    for path in sorted(set(re.findall(r'`((?:include|tests|tools|docs)/[\w/.]+\.(?:hpp|cpp|py|md))`', text))):
        if not os.path.isfile(os.path.join(root, path)):
            missing.append(f'file {path}')
    path_re = re.compile(r'`((?:include|tests)/[\w/.]+\.(?:hpp|cpp))`')  # what the names after it belong to
    for para in re.findall(r'\*\*(?:Implemented in|Tested by)\*\*.*?(?:\n\n|\Z)', text, re.S):
        para = ' '.join(para.split())
        pieces = path_re.split(para)  # [text, path, text, path, text, ...]
        for i in range(1, len(pieces), 2):
            path, body = pieces[i], pieces[i + 1]
            full = os.path.join(root, path)
            if not os.path.isfile(full):
                continue
            source = open(full, encoding='utf-8').read()
            if path.startswith('tests/'):
                for name in re.findall(r'"([^"]+)"', body):
                    if '"' + name + '"' not in source:
                        missing.append(f'test case "{name}" in {path}')
            else:
                for sym in re.findall(r'`([A-Za-z_][A-Za-z0-9_:]*)`', body):
                    word = sym.split('::')[-1]
                    if not re.search(r'\b' + re.escape(word) + r'\b', source):
                        missing.append(f'{sym} in {path}')
    for m in missing:
        print('  missing:', m)
    print(f"references in docs/math.md: {'all found' if not missing else str(len(missing)) + ' missing'}")
    return not missing


if __name__ == '__main__':
    sys.exit(0 if check_references() else 1)
