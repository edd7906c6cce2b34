#!/usr/bin/env bash
# Checks that every C++ file of the repository is formatted as .clang-format
# says (run by ctest as the test source_formatted). Formatting differs from
# one clang-format version to the next: the project's is Debian bookworm's
# clang-format 14, which scripts/setup.sh installs.
#   bash scripts/check_format.sh          lists the files that are not
#   bash scripts/check_format.sh --fix    formats them in place
set -euo pipefail
cd "$(dirname "$0")/.."

format=$(command -v clang-format-14 || true)
if [ -z "$format" ]; then
  echo "check_format: clang-format-14 not found (bash scripts/setup.sh installs it)"
  exit 1
fi

files=$(git ls-files '*.cc' '*.h' '*.h.in' 2>/dev/null || \
        find applications benchmarks include source tests \
             -name '*.cc' -o -name '*.h' -o -name '*.h.in')
if [ "${1:-}" = "--fix" ]; then
  for f in $files; do "$format" -i "$f"; done
  exit 0
fi
unformatted=""
for f in $files; do
  "$format" --dry-run --Werror "$f" >/dev/null 2>&1 || unformatted="$unformatted $f"
done
if [ -n "$unformatted" ]; then
  echo "check_format: not formatted as .clang-format says (fix with:"
  echo "bash scripts/check_format.sh --fix):"
  for f in $unformatted; do echo "  $f"; done
  exit 1
fi
echo "check_format: $(echo $files | wc -w) files formatted"
