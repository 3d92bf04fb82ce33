#!/usr/bin/env bash
# Installs the npm packages the tests use: third-party readers and clients that check
# plexus's files and protocols (tests/ecosystem: @mcap/core and Foxglove's OMG IDL parser and
# CDR decoder read plexus's MCAP recordings). Every folder under tests/ with a
# package-lock.json gets `npm ci`: exactly the locked versions.
#
# Idempotent, like install_deps.sh: a folder whose node_modules was installed from its
# current lock file is left alone. Node.js and npm: the machine's (Node 20 is what the tests
# ran on); where there is no npm, Debian's nodejs and npm packages are installed. Needs the
# npm registry (registry.npmjs.org) the first time.
set -euo pipefail
cd "$(dirname "$0")/../.."

if ! command -v npm > /dev/null 2>&1; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "install_npm: installing Debian's nodejs and npm"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends nodejs npm
fi

n=0
while IFS= read -r lock; do
  dir=$(dirname "$lock")
  n=$((n + 1))
  # npm ci writes node_modules/.package-lock.json; newer than the lock file: installed from it.
  if [ -f "$dir/node_modules/.package-lock.json" ] && [ "$dir/node_modules/.package-lock.json" -nt "$lock" ]; then
    echo "install_npm: $dir: up to date"
    continue
  fi
  echo "install_npm: $dir: npm ci (node $(node --version))"
  (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
done < <(find tests -name package-lock.json -not -path '*/node_modules/*' | sort)
echo "install_npm: $n folder(s) with npm packages"
