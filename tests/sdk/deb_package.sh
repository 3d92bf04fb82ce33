#!/usr/bin/env bash
# The Debian package (docs/sdk.md, "Installing"): `cpack -G DEB` in the build tree makes
# plexus_<version>_amd64.deb; its control fields and contents are checked with dpkg-deb,
# lintian reports on it (errors listed, not fatal: see docs/sdk.md), and apt resolves its
# dependencies on this machine (apt-get install --simulate, nothing installed).
# Usage: deb_package.sh BUILD_DIR OUT_DIR
set -euo pipefail
# Searches read here-strings, never `echo "$big" | grep -q`: grep -q leaves at its first
# match, echo then dies of SIGPIPE on a list longer than the pipe's buffer, and pipefail
# turns that into a failed search (a clean-clone CI run, 2026-11-29: "the package lacks
# ./usr/bin/component_host" for a package that had it).
build=$(realpath "$1") out=$2
rm -rf "$out" && mkdir -p "$out" && out=$(realpath "$out")
(cd "$out" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" > cpack.log 2>&1) ||
  { cat "$out/cpack.log" >&2; exit 1; }
deb=$(ls "$out"/plexus_*_amd64.deb)
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"
info=$(dpkg-deb -I "$deb")
echo "$info" | grep -E "^ (Package|Version|Architecture|Depends|Installed-Size):"
for field in "Package: plexus" "Architecture: amd64" "Depends:.*libfastrtps2.9" "Depends:.*libddsc0debian" \
             "Depends:.*libyaml-cpp0.7"; do
  grep -Eq "^ $field" <<< "$info" || { echo "FAIL: control lacks '$field'" >&2; exit 1; }
done
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/plexus ./usr/bin/plexus_idlgen ./usr/bin/plant_simulator ./usr/bin/joint_controller \
         ./usr/bin/component_host ./usr/lib/libplexus_runtime.so ./usr/lib/libplant_simulator_components.so \
         ./usr/lib/cmake/plexus/plexusConfig.cmake ./usr/lib/cmake/plexus/plexusConfigVersion.cmake \
         ./usr/include/plexus/msg/messages.hpp ./usr/include/plexus/scenario/component.hpp \
         ./usr/share/plexus/qos.yaml ./usr/share/plexus/scenarios/four_robots.yaml ./usr/share/plexus/idl/plexus/msg/pose.idl; do
  grep -qx "$f" <<< "$contents" || { echo "FAIL: the package lacks $f" >&2; exit 1; }
done
# No test helper, and no private header (src/), in the package.
if grep -Eq "/(topic_peer|plexus_test_peer|native_[a-z_]+|[a-z_]+_tests)$|/src/" <<< "$contents"; then
  echo "FAIL: test helpers or private headers in the package" >&2; exit 1
fi
echo "files: $(echo "$contents" | grep -vc '/$')"
if command -v lintian > /dev/null; then
  lintian --no-tag-display-limit "$deb" > "$out/lintian.txt" 2>&1 || true
  echo "lintian: $(grep -c '^E:' "$out/lintian.txt" || true) errors, $(grep -c '^W:' "$out/lintian.txt" || true) warnings ($out/lintian.txt)"
fi
apt-get install --simulate -q "$deb" > "$out/apt.txt" 2>&1 || { cat "$out/apt.txt" >&2; echo "FAIL: apt cannot resolve the dependencies" >&2; exit 1; }
grep -E "^Inst plexus " "$out/apt.txt" || { cat "$out/apt.txt" >&2; echo "FAIL: apt would not install plexus" >&2; exit 1; }
echo "PASS"
