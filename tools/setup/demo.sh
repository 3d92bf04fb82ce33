#!/usr/bin/env bash
# The README's first command: install dependencies, build, run the main job: all four
# robot types and every service, launched as separate processes over DDS on loopback
# (deploy/scenarios/four_robots.yaml), with a live status line, then the comparison with
# the papers' figures and the plots (plexus report). The exit code is the run's: 1 when a
# paper figure is missed (the table says which; docs/algorithms/*.md say why).
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/setup/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
exec build/bin/plexus launch deploy/scenarios/four_robots.yaml --report "$@"
