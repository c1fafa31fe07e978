# Sourced by the benchmark scripts. isphdem_binary ROOT [PATH]: the isphdem to time, on stdout.
# Without PATH it is ROOT/build/coupling/isphdem, configured and built first if needed; either
# way the script stops unless the file is executable.
isphdem_binary() {
  local root=$1 bin=${2:-}
  if [[ -z $bin ]]; then
    bin=$root/build/coupling/isphdem
    [[ -f $root/build/CMakeCache.txt ]] || cmake -S "$root" -B "$root/build" >/dev/null
    cmake --build "$root/build" -j2 --target isphdem >/dev/null
  fi
  [[ -x $bin ]] || { echo "no isphdem binary at $bin" >&2; return 1; }
  echo "$bin"
}
