#!/usr/bin/env bash
# Builds Catch2 version 3 from Debian's source (the catch2 3.7.1 package of Debian 13, the
# upstream tarball as Debian ships it, checked against its SHA-256) and installs it into
# build/catch2-v3/prefix, for the preset clang (CMakePresets.json): apse's tests built with
# clang++ against Catch2 3 on a machine whose distribution ships Catch2 2. Catch2 is built with
# the same compiler. Idempotent: does nothing if the prefix is already there. Needs cmake, ninja,
# clang++ and network access to deb.debian.org.
set -euo pipefail
cd "$(dirname "$0")/.."
version=3.7.1
sha256=c991b247a1a0d7bb9c39aa35faf0fe9e19764213f28ffba3109388e62ee0269c
dir=build/catch2-v3
[ -f "$dir/prefix/lib/cmake/Catch2/Catch2Config.cmake" ] && exit 0
mkdir -p "$dir"
tarball="$dir/catch2_$version.orig.tar.gz"
if [ ! -f "$tarball" ]; then
  url=http://deb.debian.org/debian/pool/main/c/catch2/catch2_$version.orig.tar.gz
  if command -v curl > /dev/null; then curl -sSfLo "$tarball.part" "$url"; else wget -qO "$tarball.part" "$url"; fi
  mv "$tarball.part" "$tarball"
fi
echo "$sha256  $tarball" | sha256sum -c --quiet
rm -rf "$dir/src" "$dir/build"
mkdir -p "$dir/src"
tar xzf "$tarball" -C "$dir/src" --strip-components=1
cmake -S "$dir/src" -B "$dir/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DCATCH_INSTALL_DOCS=OFF -DCATCH_INSTALL_EXTRAS=ON -DBUILD_TESTING=OFF > "$dir/configure.log"
cmake --build "$dir/build" -j "${APSE_JOBS:-2}" > "$dir/build.log"
cmake --install "$dir/build" --prefix "$dir/prefix" > "$dir/install.log"
echo "== Catch2 $version installed in $dir/prefix"
