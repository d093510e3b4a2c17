#!/usr/bin/env python3
"""Lists the files of apse's headers that one sample of the recommended map (TabulatedLdRadialMap,
double and float) runs through, and fails when there are more than --max.

tools/sample_path.cpp is built without optimisation and with -finstrument-functions (every function
entered is reported, inlined ones included), run, and the addresses it prints are mapped to their
source files by addr2line; files outside include/apse/ (GLM, the standard library) are left out.

    python3 tools/sample_path.py [--compiler g++] [--max N]
"""
import argparse
import os
import subprocess
import sys
import tempfile


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--compiler', default='g++')
    parser.add_argument('--max', type=int, default=None)
    args = parser.parse_args()
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
    include = os.path.join(root, 'include')
    with tempfile.TemporaryDirectory() as tmp:
        exe = os.path.join(tmp, 'sample_path')
        # -no-pie: the printed addresses are the ones in the file that addr2line reads
        subprocess.run([args.compiler, '-std=c++17', '-O0', '-g', '-finstrument-functions', '-no-pie',
                        '-I', include, os.path.join(root, 'tools', 'sample_path.cpp'), '-o', exe], check=True)
        addresses = sorted(set(subprocess.run([exe], capture_output=True, text=True, check=True).stdout.split()))
        lines = subprocess.run(['addr2line', '-f', '-C', '-e', exe] + addresses, capture_output=True, text=True,
                               check=True).stdout.splitlines()
    apse_dir = os.path.join(include, 'apse') + os.sep
    functions = {}
    for name, place in zip(lines[0::2], lines[1::2]):
        path = os.path.normpath(place.rsplit(':', 1)[0])
        if path.startswith(apse_dir):
            functions.setdefault(os.path.relpath(path, include), set()).add(name)
    if not functions:
        print('sample_path: no apse function recorded (is the build instrumented?)')
        return 1
    for path in sorted(functions):
        print(f'{path}: {len(functions[path])} function(s)')
        for name in sorted(functions[path]):
            print(f'    {name}')
    print(f'{len(functions)} files on the path of one TabulatedLdRadialMap sample')
    if args.max is not None and len(functions) > args.max:
        print(f'more than {args.max}')
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
