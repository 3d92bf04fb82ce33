#!/usr/bin/env bash
# record_replay.sh BIN_DIR VENDOR DOMAIN WORK_DIR [REPLAY_ARGS...]: records 50 samples of a
# live topic, replays them (--verbatim, then REPLAY_ARGS: default `--rate-scale 2`) while
# recording again, and checks that both recordings hold the same samples (same count and
# CDR digest per topic, from `plexus replay --summary`). EXT=sqlite: SQLite recordings
# (default mcap).
set -eu
bin=$1 vendor=$2 domain=$3 work=$4
shift 4
[ $# -gt 0 ] || set -- --rate-scale 2
mkdir -p "$work"
ext=${EXT:-mcap}
a=$work/a.$ext b=$work/b.$ext
rm -f "$a" "$b"
"$bin/tests/topic_peer" pub --dds "$vendor" --domain "$domain" --topic tools/replayed --profile sensor_reliable --rate 100 --count 50 --duration 30 --wait-reader &
peer=$!
"$bin/plexus" record --dds "$vendor" --domain "$domain" --topics tools/replayed -o "$a" --count 50 --duration 25 --wait 10
wait $peer || true
"$bin/plexus" record --dds "$vendor" --domain "$domain" --topics tools/replayed -o "$b" --count 50 --duration 25 --wait 10 &
rec=$!
sleep 0.2
"$bin/plexus" replay --dds "$vendor" --domain "$domain" --verbatim --wait 10 "$@" "$a"
wait $rec
sa=$("$bin/plexus" replay --summary "$a")
sb=$("$bin/plexus" replay --summary "$b")
echo "recorded: $sa"
echo "replayed: $sb"
echo "$sa" | grep -q " 50 samples" || { echo "first recording does not hold 50 samples"; exit 1; }
[ "$(echo "$sa" | sed 's/  [0-9.]* s / /')" = "$(echo "$sb" | sed 's/  [0-9.]* s / /')" ] || { echo "replay differs from the recording"; exit 1; }
echo "record -> replay -> record: identical samples"
