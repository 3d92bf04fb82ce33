# Sourced by the tests that load a page in headless Chromium (tests/report/report_html.sh,
# tests/bench/report_renders.sh). `chrome ARGS... URL` runs it once: headless, as root with
# --no-sandbox, with every flag that keeps it off the network (and a host resolver that
# resolves no name: the pages are local files), in a fresh --user-data-dir removed on exit;
# its stderr goes to $out/chromium.log. `chromium_bin` is empty when Chromium is missing.
# Sets an EXIT trap.
chromium_bin=$(command -v chromium || command -v chromium-browser || true)
chrome_profiles=()
chrome_cleanup() { for p in "${chrome_profiles[@]}"; do rm -rf "$p"; done; }
trap chrome_cleanup EXIT
chrome() {
  local profile
  profile=$(mktemp -d "${TMPDIR:-/tmp}/plexus-chromium.XXXXXX")
  chrome_profiles+=("$profile")
  timeout 120 "$chromium_bin" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync --disable-extensions \
    --disable-default-apps --no-default-browser-check --mute-audio --no-proxy-server \
    --host-resolver-rules="MAP * ~NOTFOUND" --user-data-dir="$profile" \
    --virtual-time-budget=10000 "$@" 2>>"$out/chromium.log"
}
