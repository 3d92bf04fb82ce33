#!/usr/bin/env bash
# record_convert.sh PLEXUS SCENARIO DOMAIN WORK_DIR: a SQLite recording (plexus's format
# before MCAP) stays readable, and `plexus record convert` writes the same samples as MCAP:
# `plexus replay --summary` (count and CDR digest per topic) is the same for both,
# `plexus record info` gives the same counts, `plexus topic echo --recording` prints the same
# samples from both, and names a topic that is not there (exit 2, one line).
set -eu
plexus=$1 scenario=$2 domain=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
"$plexus" launch "$scenario" --set duration=2 --domain "$domain" --record "$work/run.sqlite" --out "$work/run" --quiet \
  > /dev/null 2>&1 || true  # a 2 s run may miss its expectations (exit 1): the recording is what counts
[ -s "$work/run.sqlite" ] || { echo "no SQLite recording made"; exit 1; }
"$plexus" record convert "$work/run.sqlite" "$work/run.mcap"
a=$("$plexus" replay --summary "$work/run.sqlite")
b=$("$plexus" replay --summary "$work/run.mcap")
echo "$a"
[ -n "$a" ] && [ "$a" = "$b" ] || { echo "the MCAP conversion holds other samples:"; echo "$b"; exit 1; }
ia=$("$plexus" record info "$work/run.sqlite" --json | jq -c '{messages, topics, c: [.channels[] | [.topic, .type, .messages]]}')
ib=$("$plexus" record info "$work/run.mcap" --json | jq -c '{messages, topics, c: [.channels[] | [.topic, .type, .messages]]}')
[ "$ia" = "$ib" ] || { echo "record info differs: $ia / $ib"; exit 1; }
"$plexus" record info "$work/run.mcap"
ea=$("$plexus" topic echo r1/rfid --recording "$work/run.sqlite" --json --count 5)
eb=$("$plexus" topic echo r1/rfid --recording "$work/run.mcap" --json --count 5)
[ "$(echo "$ea" | grep -c .)" -eq 5 ] && [ "$ea" = "$eb" ] || { echo "topic echo --recording differs: $ea / $eb"; exit 1; }
"$(dirname "$0")/../scripts/expect_exit.sh" 2 "--recording: topic 'nope' is not in .*run.mcap \\(topics: " \
  "$plexus" topic echo nope --recording "$work/run.mcap"
echo "SQLite and its MCAP conversion: the same samples"
