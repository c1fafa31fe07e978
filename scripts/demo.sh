#!/usr/bin/env bash
# Installs what is missing, builds, and runs the demo: the 2D Taylor-Green vortex at Re = 100 to
# t = 1 s, then writes two pictures (the speed field and the amplitude decay against the exact one).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
out="${1:-$root/out/taylor_green_2d}"
"${ISPHDEM_BUILD_DIR:-$root/build}/coupling/isphdem" run "$root/examples/taylor_green_2d/case.toml" --out "$out"
last=$(ls "$out"/snap_*.h5 | sort | tail -n 1)
/usr/bin/python3 "$root/scripts/plot_fluid.py" "$last" --field speed --quiver 7 -o "$out/taylor_green.png"
/usr/bin/python3 "$root/scripts/plot_taylor_green.py" "$out"
echo "demo: results in $out (open fluid.xdmf in ParaView; pictures taylor_green.png, decay.png)"
