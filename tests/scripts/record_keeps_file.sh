#!/usr/bin/env bash
# record_keeps_file.sh PLEXUS DOMAIN OUT: a recording that fails (no writer on its topic)
# leaves an existing file at -o untouched and no partial file behind.
set -u
plexus=$1 domain=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
echo "precious" > "$out/run.sqlite"
"$plexus" record -o "$out/run.sqlite" --topics nothing/here --wait 1 --duration 1 --domain "$domain"
rc=$?
[ $rc -ne 0 ] || { echo "the recording should have failed"; exit 1; }
[ "$(cat "$out/run.sqlite")" = precious ] || { echo "the existing file was replaced"; exit 1; }
[ ! -e "$out/run.sqlite.partial" ] || { echo "a partial file was left behind"; exit 1; }
echo "exit $rc, existing file intact"
