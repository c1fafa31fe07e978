#!/usr/bin/env bash
# Regenerates the study charts and tables of docs/study.md: runs every study of examples/studies/
# (or the ones named) into out/studies/<name>/ and copies its study.csv and study.png to
# docs/study/<name>.csv, <name>.png (error against cost), <name>_stability.png (stability map) and
# <name>_convergence.png with <name>_convergence.csv (metrics against a step), the charts where the
# study draws them. Points finished in an earlier call are not run again; delete
# out/studies/<name> to measure afresh. Run it on a quiet machine: the wall times are the chart.
#   scripts/study_docs.sh [NAME ...] [-- isphdem study options, e.g. -j 2]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
names=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do names+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
if [ ${#names[@]} -eq 0 ]; then
  for f in "$root"/examples/studies/*.toml; do names+=("$(basename "$f" .toml)"); done
fi
[ -x "$root/build/coupling/isphdem" ] || bash "$root/scripts/build.sh"
mkdir -p "$root/docs/study"
for name in "${names[@]}"; do
  out="$root/out/studies/$name"
  "$root/build/coupling/isphdem" study "$root/examples/studies/$name.toml" --out "$out" "$@"
  cp "$out/study.csv" "$root/docs/study/$name.csv"
  echo "study_docs: docs/study/$name.csv"
  # study.png needs a [reference] metric, stability.png a [plot] stability, convergence.png a
  # [plot] convergence: each where drawn.
  for chart in study stability convergence; do
    if [ -f "$out/$chart.png" ]; then
      suffix=""; [ "$chart" != study ] && suffix="_$chart"
      cp "$out/$chart.png" "$root/docs/study/$name$suffix.png"
      echo "study_docs: docs/study/$name$suffix.png"
    fi
  done
  if [ -f "$out/convergence.csv" ]; then
    cp "$out/convergence.csv" "$root/docs/study/${name}_convergence.csv"
    echo "study_docs: docs/study/${name}_convergence.csv"
  fi
done
