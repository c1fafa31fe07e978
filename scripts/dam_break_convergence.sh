#!/usr/bin/env bash
# Dam-break convergence (docs/fluid.md): examples/dam_break_2d at a/dx = 20, 40, 80, the surge
# front of each (bench/dam_break/front.py, the validation test's definition) against the
# instant-release interFoam reference and Martin & Moyce. Writes out/dam_break_convergence/ and
# docs/fluid/dam_break_convergence.csv and .png. a/dx 80 takes about 4 min on one core.
#   scripts/dam_break_convergence.sh [A_OVER_DX ...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
res=("$@"); [ ${#res[@]} -eq 0 ] && res=(20 40 80)
[ -x "$root/build/coupling/isphdem" ] || bash "$root/scripts/build.sh"
out="$root/out/dam_break_convergence"
mkdir -p "$out" "$root/docs/fluid"
jsons=()
for n in "${res[@]}"; do
  dx=$(/usr/bin/python3 -c "print(0.1 / $n)")
  echo "dam_break_convergence: a/dx = $n (dx = $dx m)"
  start=$(date +%s.%N)
  OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} "$root/build/coupling/isphdem" run \
    "$root/examples/dam_break_2d/case.toml" --out "$out/a$n" \
    --set particles.spacing="$dx" --set output.interval=0.005
  wall=$(/usr/bin/python3 -c "print(round($(date +%s.%N) - $start, 1))")
  /usr/bin/python3 "$root/bench/dam_break/front.py" "$out/a$n" --dx "$dx" --json "$out/a$n.json"
  /usr/bin/python3 - "$out/a$n.json" "$n" "$wall" <<'PY'
import json, sys
path, n, wall = sys.argv[1:]
r = json.load(open(path)); r["a_over_dx"] = int(n); r["wall_s"] = float(wall)
json.dump(r, open(path, "w"), indent=1)
PY
  jsons+=("$out/a$n.json")
done
/usr/bin/python3 "$root/scripts/plot_dam_break_convergence.py" "$root/docs/fluid/dam_break_convergence" "${jsons[@]}"
