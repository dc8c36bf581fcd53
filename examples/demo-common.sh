# Sourced by the examples' run.sh scripts: the eposp command (the script's first argument, or
# build/device/eposp), the example's own folder ($here), the folder the outputs go to ($out:
# EPOSP_DEMO_DIR, or build/demo) and section headings.
set -euo pipefail
eposp=$(realpath "${1:-build/device/eposp}")
here=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
out=${EPOSP_DEMO_DIR:-build/demo}
mkdir -p "$out"

section() { printf '\n\033[1m%s\033[0m\n' "$*"; }
