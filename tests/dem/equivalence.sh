#!/usr/bin/env bash
# Same granular script under stock liggghts, under `isphdem dem`, and under `isphdem dem` with
# fix couple/isph (zero loads): the final positions and velocities (printed with %.17g, so
# equal text means equal doubles) must be identical.
# usage: equivalence.sh LIGGGHTS ISPHDEM SCRIPT NSTEPS WORKDIR [NP]
set -euo pipefail
liggghts=$1 isphdem=$2 script=$3 nsteps=$4 work=$5 np=${6:-1}
mkdir -p "$work" && cd "$work"
launch=()
if [ "$np" -gt 1 ]; then launch=(mpirun --allow-run-as-root --oversubscribe -np "$np"); fi
run() {  # name, command...
  local name=$1; shift
  "${launch[@]}" "$@" -var nsteps "$nsteps" -var out "$name.dump" -log none -echo screen -screen "$name.screen"
}
run stock "$liggghts" -in "$script"
run driver "$isphdem" dem "$script"
run coupled "$isphdem" dem "$script" -var couple 1
grep -q "couple/isph" coupled.screen || { echo "coupled run did not create the fix"; exit 1; }
n=$(($(wc -l < stock.dump) - 9))
[ "$n" -gt 100 ] || { echo "only $n atoms in the dump"; exit 1; }
for other in driver coupled; do
  if ! cmp -s stock.dump "$other.dump"; then
    echo "FAIL: $other differs from stock liggghts after $nsteps steps ($np ranks):"
    diff stock.dump "$other.dump" | head -5
    exit 1
  fi
done
echo "identical final x, v, omega of $n atoms after $nsteps steps on $np rank(s): stock liggghts," \
     "isphdem dem, isphdem dem + fix couple/isph"
