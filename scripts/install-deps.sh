#!/usr/bin/env bash
# Installs the Debian 12 (bookworm) packages TideSPH needs to build, test and benchmark; with
# --browser also what the browser test of tide serve needs (node, npm, chromium), which the main
# job does not. Idempotent and quiet: when every package is present it changes nothing and needs
# no root.
set -euo pipefail

packages=(
  build-essential cmake          # compilers, make, CMake >= 3.22
  libeigen3-dev libtbb-dev       # core: small-vector math, the parallel layer (oneTBB)
  libhdf5-dev nlohmann-json3-dev # io: output files, scene files
  libtinyobjloader-dev           # io: Wavefront OBJ meshes
  libpng-dev                     # render: PNG frames
  libcli11-dev                   # apps: the tide command line
  libcivetweb-dev civetweb       # serve: tide serve's HTTP + WebSocket server (its CMake config needs both)
  libgtest-dev libbenchmark-dev  # tests/, bench/
  clang clang-format             # second compiler, formatting
  libclang-rt-14-dev             # sanitizer runtimes and libFuzzer for clang
  gnuplot-nox                    # plots of benchmark and validation results
)

installed() {
  [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == "install ok installed" ]]
}

has_candidate() {
  local candidate
  candidate=$(apt-cache policy "$1" 2>/dev/null | sed -n 's/^ *Candidate: *//p')
  [[ -n "$candidate" && "$candidate" != "(none)" ]]
}

# The browser test of tide serve (tests/browser/serve_test.mjs): node and npm, unless a Node.js
# is already there (it brings its own npm), and Debian's chromium. Chromium is optional: where it
# cannot be installed the browser test is skipped with the reason.
browser_packages=()
if [[ "${1:-}" == "--browser" ]]; then
  command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
  installed chromium || browser_packages+=(chromium)
fi

missing=()
for package in "${packages[@]}"; do
  installed "$package" || missing+=("$package")
done

if ((${#missing[@]} == 0 && ${#browser_packages[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi

if ((${#missing[@]} == 0 && EUID != 0)); then
  echo "install-deps: chromium is not installed (as root this script installs it); the browser test will be skipped"
  exit 0
fi

if ((EUID != 0)); then
  echo "install-deps: missing packages: ${missing[*]}" >&2
  echo "install-deps: run this script as root, or: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive

# Runs apt-get with its output held back; shows the output only if apt-get fails.
apt_get() {
  local log status=0
  log=$(mktemp)
  apt-get -q -o Dpkg::Use-Pty=0 "$@" >"$log" 2>&1 || status=$?
  if ((status != 0)); then cat "$log" >&2; fi
  rm -f "$log"
  return "$status"
}

# Refresh the package lists only when one of the missing packages has no candidate in them
# (a fresh image ships without lists); otherwise install from the lists at hand.
for package in "${missing[@]}" "${browser_packages[@]}"; do
  if ! has_candidate "$package"; then
    echo "install-deps: updating the package lists"
    apt_get update
    break
  fi
done

if ((${#browser_packages[@]} != 0)); then
  echo "install-deps: installing ${browser_packages[*]} (optional: the browser test)"
  apt_get install -y --no-install-recommends "${browser_packages[@]}" ||
    echo "install-deps: could not install ${browser_packages[*]}; the browser test will be skipped"
fi
if ((${#missing[@]} == 0)); then
  echo "install-deps: done"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
if ! apt_get install -y --no-install-recommends "${missing[@]}"; then
  # Stale lists point at files the mirror no longer has: refresh once and retry.
  echo "install-deps: install failed; updating the package lists and retrying"
  apt_get update
  apt_get install -y --no-install-recommends "${missing[@]}"
fi

still_missing=()
for package in "${missing[@]}"; do
  installed "$package" || still_missing+=("$package")
done
if ((${#still_missing[@]} != 0)); then
  echo "install-deps: could not install: ${still_missing[*]}" >&2
  exit 1
fi
echo "install-deps: done"
