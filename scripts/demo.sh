#!/usr/bin/env bash
# Installs what is missing, builds, and runs a demo.
#
#   bash scripts/demo.sh [erosion] [--docs] [OUT]   (the default; OUT: out/erosion_demo)
#   bash scripts/demo.sh fluid [OUT]                (OUT: out/taylor_green_2d)
#
# erosion: the seed's contrast on the reduced internal-erosion layer
# (examples/internal_erosion_2d/reduced.toml: 6 coarse grains, 32 fines, tank 36 mm x 40 mm).
# It packs the layer into OUT (a few seconds), then runs the same packing under both coupling
# models side by side, one thread each, at v_in = 2 cm/s for 0.5 s: unresolved (every grain as
# porosity + drag) and semi-resolved (fines so, coarse grains resolved by PMS particles). It
# writes OUT/erosion_demo.png (the two at the end, one colour scale), OUT/erosion_demo.gif and
# OUT/summary.txt (pore jets, fines moved, surface rise, wall time per model; also printed).
# --docs also copies the picture and the summary to docs/internal_erosion/demo.png and
# demo_summary.txt (the README's picture and lines).
#
# fluid: the 2D Taylor-Green vortex at Re = 100 to t = 1 s (about 10 s), then two pictures (the
# speed field and the amplitude decay against the exact one).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
what=erosion
docs=0
if [ "${1:-}" = fluid ] || [ "${1:-}" = erosion ]; then what=$1; shift; fi
if [ "${1:-}" = --docs ]; then docs=1; shift; fi
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" -- isphdem   # the program only; scripts/test.sh builds the tests
isphdem="${ISPHDEM_BUILD_DIR:-$root/build}/coupling/isphdem"

if [ "$what" = fluid ]; then
  out="${1:-$root/out/taylor_green_2d}"
  "$isphdem" run "$root/examples/taylor_green_2d/case.toml" --out "$out"
  last=$(ls "$out"/snap_*.h5 | sort | tail -n 1)
  /usr/bin/python3 "$root/scripts/plot_fluid.py" "$last" --field speed --quiver 7 -o "$out/taylor_green.png"
  /usr/bin/python3 "$root/scripts/plot_taylor_green.py" "$out"
  echo "demo: results in $out (open fluid.xdmf in ParaView; pictures taylor_green.png, decay.png)"
  exit 0
fi

out="${1:-$root/out/erosion_demo}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
case_dir="$root/examples/internal_erosion_2d"
# 2 cm/s: within 0.5 s the semi-resolved skeleton opens and lifts (surface +5.1 mm, 32 of 32 fines
# moved) while the unresolved layer stays (7 fines moved, surface 0), pore jets 14.3 against
# 4.8 v_in; at 0.5 cm/s the models differ in their jets only (the surface still in both;
# docs/internal_erosion.md, "The demo").
vin=0.02      # m/s
end=0.5       # s simulated
start=$(date +%s)

echo "demo: packing the reduced layer into $out (6 coarse grains, 32 fines)"
# The -var line of reduced.toml's header ([dem] prepare), with the restart written into OUT.
"$isphdem" dem "$case_dir/in.packing" -var case_dir "$case_dir" -var packing_dir "$out" \
  -var packing packing_reduced.restart -var nclumps 6 -var nfines 32 -var x_lo 0.010 \
  -var x_hi 0.026 -var mesh_y 0.014 -var box_x 0.036 -var box_y 0.07 \
  -log none -screen "$out/packing.screen"

echo "demo: both coupling models side by side, v_in = $vin m/s, $end s (logs in $out/*.log)"
pids=()
for model in unresolved semi-resolved; do
  OMP_NUM_THREADS=1 "$isphdem" run "$case_dir/reduced.toml" --out "$out/$model" --quiet \
    --set "dem.variables.packing_dir=\"$out\"" --set "coupling.model=\"$model\"" \
    --set inflow.velocity=$vin --set time.end=$end --set output.interval=0.025 \
    >"$out/$model.log" 2>&1 &
  pids+=($!)
done
failed=0
for i in 0 1; do
  if ! wait "${pids[$i]}"; then failed=1; fi
done
if [ $failed -ne 0 ]; then
  tail -n 20 "$out"/*.log >&2
  echo "demo: a run failed (logs above)" >&2
  exit 1
fi

/usr/bin/python3 "$root/scripts/plot_erosion.py" "$out/unresolved" "$out/semi-resolved" \
  --xlim 2 34 --ylim 4 34 --paths 0 --png "$out/erosion_demo.png" --gif "$out/erosion_demo.gif" \
  --summary "$out/summary.txt" \
  --title "Water forced up at v_in = $(/usr/bin/python3 -c "print('%g' % (100 * $vin))") cm/s through the same packed layer: two coupling models"
if [ $docs -eq 1 ]; then
  mkdir -p "$root/docs/internal_erosion"
  cp "$out/erosion_demo.png" "$root/docs/internal_erosion/demo.png"
  cp "$out/summary.txt" "$root/docs/internal_erosion/demo_summary.txt"
  echo "demo: copied the picture and the summary to docs/internal_erosion/"
fi
echo "demo: $(($(date +%s) - start)) s after the build; results in $out (erosion_demo.png," \
  "erosion_demo.gif, summary.txt; open */fluid.xdmf and */dem.xdmf in ParaView)"
