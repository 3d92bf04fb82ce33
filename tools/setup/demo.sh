#!/usr/bin/env bash
# The README's first command: install dependencies, build, run the main job.
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/setup/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
exec build/bin/plexus demo
