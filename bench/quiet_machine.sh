# Sourced by the benchmark scripts: timed runs start on a quiet machine.
#   load1       the 1-minute load average
#   busy        CPU-seconds the whole machine has used so far (for "other cores" during a run)
#   wait_quiet  waits until load1 <= LOAD_MAX, at most LOAD_WAIT seconds, and echoes the load the
#               run starts at ('!' appended when the machine never became quiet)
load1() { cut -d' ' -f1 /proc/loadavg; }
busy() { awk '/^cpu /{print ($2 + $3 + $4 + $7 + $8 + $9) / 100}' /proc/stat; }
wait_quiet() {
  local waited=0
  while /usr/bin/python3 -c "import sys; sys.exit(0 if $(load1) > $LOAD_MAX else 1)"; do
    if ((waited >= LOAD_WAIT)); then echo "$(load1)!"; return; fi
    sleep 10; waited=$((waited + 10))
  done
  load1
}
