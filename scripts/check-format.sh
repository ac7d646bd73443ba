#!/usr/bin/env bash
# Fails, naming the files, when a C++ file differs from .clang-format (clang-format 14, as
# Debian 12 ships it). Fix with: scripts/check-format.sh --fix
set -euo pipefail
cd "$(dirname "$0")/.."

mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
    clang-format -i "${files[@]}"
    exit 0
fi
# One run over every file; each difference is reported as "FILE:LINE:COL: error: ...".
mapfile -t differ < <(clang-format --dry-run --Werror "${files[@]}" 2>&1 |
    sed -n 's/^\([^: ]*\):[0-9]*:[0-9]*: error: .*/\1/p' | sort -u)
if [ ${#differ[@]} -gt 0 ]; then
    printf 'check-format: %d file(s) differ from .clang-format (scripts/check-format.sh --fix):\n' ${#differ[@]} >&2
    printf '  %s\n' "${differ[@]}" >&2
    exit 1
fi
echo "check-format: ${#files[@]} files match .clang-format"
