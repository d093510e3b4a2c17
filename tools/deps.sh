#!/usr/bin/env bash
# Installs the Debian packages apse's builds need, only those that are missing (safe to re-run).
# Sourced by tools/test.sh and tools/demo.sh; needs root (or passwordless sudo) when installing.
apse_install_deps() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "== installing: ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}
APSE_BASE_PACKAGES=(g++ cmake ninja-build libglm-dev catch2 libbenchmark-dev libstb-dev)
