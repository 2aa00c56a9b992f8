#!/usr/bin/env bash
# Fails (exit 1) when a tracked .cc/.h file is not as clang-format (the
# project's .clang-format: Google style, 100 columns) would write it, listing
# the files; `clang-format -i FILE` fixes one. Exit 77 (skip) without
# clang-format or outside a git checkout.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null 2>&1 || { echo "clang-format not installed: skipped"; exit 77; }
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "not a git checkout: skipped"; exit 77; }
bad=()
while IFS= read -r file; do
  [ -f "$file" ] || continue
  clang-format --dry-run -Werror "$file" >/dev/null 2>&1 || bad+=("$file")
done < <(git ls-files '*.cc' '*.h')
if [ ${#bad[@]} -gt 0 ]; then
  echo "not formatted (clang-format -i FILE):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "every .cc/.h file is formatted"
