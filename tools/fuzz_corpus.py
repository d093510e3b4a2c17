#!/usr/bin/env python3
"""Packs a fuzz target's seed corpus into its archive, tests/fuzz/corpus/<target>_seed_corpus.zip
(one archive per target, as OSS-Fuzz keeps them; the build extracts it for the corpus replay and
the libFuzzer run). Inputs that found a bug are not packed: they stay as named files in
tests/fuzz/regressions/<target>/.

    python3 tools/fuzz_corpus.py add <target> <dir-or-file>...   # merge new inputs into the archive
    python3 tools/fuzz_corpus.py list <target>                     # count and total size

Entries are named by the SHA-1 of their contents (as libFuzzer names them), so merging the same
input twice keeps one copy; the archive is written deterministically (sorted names, fixed
timestamps and permissions), so an unchanged corpus gives a byte-identical file.
"""

import hashlib
import os
import sys
import zipfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
CORPUS = os.path.join(ROOT, "tests", "fuzz", "corpus")


def archive_of(target):
    return os.path.join(CORPUS, target + "_seed_corpus.zip")


def read_archive(path):
    entries = {}
    if os.path.exists(path):
        with zipfile.ZipFile(path) as z:
            for name in z.namelist():
                entries[name] = z.read(name)
    return entries


def write_archive(path, entries):
    tmp = path + ".tmp"
    with zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as z:
        for name in sorted(entries):
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            z.writestr(info, entries[name])
    os.replace(tmp, path)


def inputs(paths):
    for p in paths:
        if os.path.isdir(p):
            for name in sorted(os.listdir(p)):
                f = os.path.join(p, name)
                if os.path.isfile(f):
                    yield f
        else:
            yield p


def main(argv):
    if len(argv) < 3 or argv[1] not in ("add", "list"):
        print(__doc__, file=sys.stderr)
        return 2
    target = argv[2]
    path = archive_of(target)
    entries = read_archive(path)
    if argv[1] == "list":
        print(f"{path}: {len(entries)} inputs, {sum(len(v) for v in entries.values())} bytes")
        return 0
    added = 0
    for f in inputs(argv[3:]):
        with open(f, "rb") as fh:
            data = fh.read()
        name = hashlib.sha1(data).hexdigest()
        if name not in entries:
            entries[name] = data
            added += 1
    write_archive(path, entries)
    print(f"{path}: {added} new inputs, {len(entries)} in all")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
