#!/bin/sh
# Steiner points and seconds of two sweepcdt binaries' default command on the same files, and
# `sweepcdt check` of the second's output (exit code; 0: a verified CDT). One run each, in turn.
# usage: bench/compare_counts.sh SWEEPCDT_BEFORE SWEEPCDT_AFTER FILE...
# Prints per file: exit codes before/after, Steiner points before -> after, seconds before -> after, check.
set -u
[ $# -ge 3 ] || { echo "usage: $0 SWEEPCDT_BEFORE SWEEPCDT_AFTER FILE..." >&2; exit 2; }
before=$1
after=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
points() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['files'][0].get('steiner_points', '-'))" "$1" 2>/dev/null || echo -; }
for f in "$@"; do
  /usr/bin/time -f "%e" -o "$work/ta" "$before" "$f" -o "$work/a.mesh" -q --stats "$work/a.json" >/dev/null 2>&1; a=$?
  /usr/bin/time -f "%e" -o "$work/tb" "$after" "$f" -o "$work/b.mesh" -q --stats "$work/b.json" >/dev/null 2>&1; b=$?
  c=-
  if [ $b -eq 0 ]; then "$after" check "$f" "$work/b.mesh" >/dev/null 2>&1; c=$?; fi
  echo "$(basename "$f") exit $a/$b points $(points "$work/a.json") -> $(points "$work/b.json") s $(tail -1 "$work/ta") -> $(tail -1 "$work/tb") check=$c"
  rm -f "$work"/a.* "$work"/b.*
done
