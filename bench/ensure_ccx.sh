# Sourced by the CalculiX benches: installs Debian's calculix-ccx when ccx is missing.
# usage: source bench/ensure_ccx.sh <bench name>
if ! command -v ccx >/dev/null 2>&1; then
  echo "$1: installing calculix-ccx" >&2
  apt-get install -y calculix-ccx >/dev/null
fi
