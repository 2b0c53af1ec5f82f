#!/usr/bin/env bash
# The test command: installs the dependencies (Debian bookworm), builds in Release,
# and runs every test with ctest. Usage: bash tools/test.sh [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
jobs="${DYNVO_JOBS:-$(nproc)}"

bash "$root/tools/install_deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
cd "$build"
ctest --output-on-failure -j "$jobs" "$@"
