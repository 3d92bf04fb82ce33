#!/usr/bin/env bash
# self_contained.sh SOURCE_DIR: fails if a file of the repository refers to a place outside
# it. A user's clone (or a tarball) holds only the repository, so the papers' references
# are in docs/papers.md and the architecture in docs/architecture.md.
#
# Files checked: with a .git in SOURCE_DIR, every file git knows (tracked, plus new files not
# ignored: `git ls-files --cached --others --exclude-standard`); without one (a tarball, an
# export), every file under SOURCE_DIR except build*/ folders, runs/ and .git. Binary files
# are skipped.
#
# The patterns are assembled from pieces so that this script does not match itself.
set -u
root=${1:?usage: self_contained.sh SOURCE_DIR}
cd "$root" || { echo "self_contained: cannot enter $root"; exit 2; }

patterns=(
  "../""shared"            # the old sibling folder of design notes and paper texts
  "PAPERS"".md"            # the paper brief that lived there
  "DESIGN"".md"            # the design target that lived there
  "/""work""/"             # absolute paths into the machine the project was built on
)
grep_args=()
for p in "${patterns[@]}"; do
  grep_args+=(-e "$p")
done

list_files() {
  if [ -e .git ] && git rev-parse --git-dir >/dev/null 2>&1; then
    git ls-files -z --cached --others --exclude-standard
  else
    find . \( -path ./.git -o -path './build*' -o -path ./runs \) -prune -o -type f -print0 | sed -z 's|^\./||'
  fi
}

# -s: a tracked file deleted in the work tree is not an error; -I: skip binary files.
hits=$(list_files | xargs -0 -r grep -n -s -I -F "${grep_args[@]}" -- /dev/null)

if [ -n "$hits" ]; then
  files=$(printf '%s\n' "$hits" | cut -d: -f1 | sort -u)
  echo "self_contained: $(printf '%s\n' "$files" | wc -l) file(s) refer to paths outside the repository"
  echo "(cite docs/papers.md for the papers, docs/architecture.md for the design):"
  printf '%s\n' "$files" | sed 's/^/  /'
  echo "references:"
  printf '%s\n' "$hits" | sed 's/^/  /'
  exit 1
fi
echo "self_contained: $(list_files | tr -cd '\0' | wc -c) files checked, none refers outside the repository"
