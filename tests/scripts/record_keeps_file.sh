#!/usr/bin/env bash
# record_keeps_file.sh PLEXUS DOMAIN OUT: a recording that fails (no writer on its topic)
# leaves an existing file at -o untouched and no partial file behind, MCAP and SQLite alike.
set -u
plexus=$1 domain=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
for ext in mcap sqlite; do
  f=$out/run.$ext
  echo "precious" > "$f"
  "$plexus" record -o "$f" --topics nothing/here --wait 1 --duration 1 --domain "$domain"
  rc=$?
  [ $rc -ne 0 ] || { echo "$ext: the recording should have failed"; exit 1; }
  [ "$(cat "$f")" = precious ] || { echo "$ext: the existing file was replaced"; exit 1; }
  [ "$(ls "$out" | grep -c "run.$ext")" -eq 1 ] || { echo "$ext: a partial file was left behind: $(ls "$out")"; exit 1; }
  echo "$ext: exit $rc, existing file intact"
done
