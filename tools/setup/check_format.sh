#!/usr/bin/env bash
# The style check (.clang-format, Google style at 120 columns): every C++ file git tracks is
# as clang-format would write it. Lists the files that are not, exit 1. Run by ctest
# (style.clang_format) and by hand; `clang-format -i FILE` fixes one.
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v clang-format > /dev/null || { echo "check_format: clang-format not installed (tools/setup/install_deps.sh)" >&2; exit 2; }
files=$(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')
bad=$(echo "$files" | xargs -P "$(nproc)" -n 32 clang-format --dry-run 2>&1 | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: warning: code should be clang-formatted.*/\1/p' | sort -u)
if [ -n "$bad" ]; then
  echo "$bad" | sed 's/^/not formatted (clang-format -i): /' >&2
  exit 1
fi
echo "check_format: $(echo "$files" | wc -l) files formatted"
