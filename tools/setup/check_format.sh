#!/usr/bin/env bash
# The style check (.clang-format, Google style at 120 columns): every C++ file git tracks is
# as clang-format would write it. Lists the files that are not, exit 1. Run by ctest
# (style.clang_format) and by hand; `clang-format -i FILE` fixes one.
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v clang-format > /dev/null || { echo "check_format: clang-format not installed (tools/setup/install_deps.sh)" >&2; exit 2; }
bad=()
while IFS= read -r f; do
  clang-format --dry-run --Werror "$f" > /dev/null 2>&1 || bad+=("$f")
done < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')
if [ ${#bad[@]} -gt 0 ]; then
  printf 'not formatted (clang-format -i): %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "check_format: $(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc' | wc -l) files formatted"
