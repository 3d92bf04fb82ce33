#!/usr/bin/env bash
# Installs everything plexus needs to build, test and run, from Debian 12 packages.
# Idempotent: packages already installed are left alone. Run as root (or with sudo).
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake pkg-config git
  # DDS: Fast DDS 2.9 + fastddsgen, Cyclone DDS 0.10 + idlc + ddsperf
  libfastrtps-dev libfastcdr-dev fastddsgen fastdds-tools
  cyclonedds-dev cyclonedds-tools
  # libraries
  libeigen3-dev libspdlog-dev libfmt-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  liborocos-kdl-dev libfftw3-dev libsqlite3-dev
  # MCAP recordings (common/mcap): zstd and LZ4 chunk compression, zlib's CRC-32
  libzstd-dev liblz4-dev zlib1g-dev
  # the Foxglove WebSocket bridge and plexus launch --monitor (common/web): websocketpp on
  # standalone asio; the monitor's page plots with dygraphs
  libwebsocketpp-dev libasio-dev libjs-dygraphs
  # tests and benchmarks; clang and its libFuzzer runtime for the fuzz targets (tests/fuzz)
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev
  # tools used at run time: plots, loop-jitter baseline, network namespaces for multi-host tests
  gnuplot-nox rt-tests iproute2 procps
  # headless Chromium: renders report.html (tests/report) and the monitor's page (tests/ecosystem)
  chromium chromium-driver
  # plexus launch over ssh (and its tests: an sshd per namespace), systemd-analyze for the units, jq in the tests
  openssh-client openssh-server systemd jq
  # test scripts that read JSON and open sockets (tests/bench, tests/first_hour, tests/ecosystem)
  python3
  # DDS Security (docs/security.md): the test PKI script, OpenSSL for the checks, captures
  openssl libssl-dev tcpdump
  # fault tests (tests/fault): packet loss and partitions inside network namespaces
  nftables
  # the Debian package's check (tests/sdk/deb_package.sh); clang-format for the style check
  lintian clang-format
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
