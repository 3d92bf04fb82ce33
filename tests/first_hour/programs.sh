#!/usr/bin/env bash
# programs.sh BIN: the programs a user runs are build/bin's files, and each answers --version
# with "<name> X.Y.Z" (issue 31: helpers without --version and test binaries sat among them).
# Test programs live in BIN/tests (cmake/PlexusTesting.cmake, plexus_place_test_programs).
set -u
bin=$1
fail=0 n=0
for f in "$bin"/*; do
  [ -f "$f" ] && [ -x "$f" ] || continue
  name=$(basename "$f")
  n=$((n + 1))
  out=$(timeout 10 "$f" --version < /dev/null 2> /dev/null)
  rc=$?
  [ "$rc" = 0 ] && [[ "$out" =~ ^$name\ [0-9]+\.[0-9]+\.[0-9]+$ ]] ||
    { echo "FAIL: $name --version: exit $rc, '$out'"; fail=1; }
  case $name in *_tests | *_peer | *_probe | topic_peer | bad_sample_publisher | native_*)
    echo "FAIL: $name is a test program in $bin (it belongs in $bin/tests)"; fail=1 ;;
  esac
done
[ "$n" -ge 15 ] || { echo "FAIL: only $n programs in $bin"; fail=1; }
[ -d "$bin/tests" ] && ls "$bin/tests" | grep -q "_tests$" || { echo "FAIL: no test binaries in $bin/tests"; fail=1; }
echo "$n programs in $bin, each with --version"
exit $fail
