#!/usr/bin/env bash
# The layers and their allowed edges (docs/architecture.md). Each layer names
# the layers it may include; anything else is an error, named with file, line
# and the rule broken. An allowed-edge table, not a rank order: quantize may
# not include render although render sits "lower" in a listing, because the
# graph has two branches over foundation (render -> lht -> loader -> exporter;
# quantize -> devices) and io beside them. Inside render/, lht/ and devices/
# the sub-folders have rules of their own (the same table form below).
# Run by scripts/test.sh (so by CI).
#   scripts/check-layers.sh
set -euo pipefail
cd "$(dirname "$0")/.."

# Layer: the layers it may include besides itself. tests/, bench/ and fuzz/
# sit above all of them and are not checked. firmware/ (docs/firmware.md) is
# the core without files, parsers or transports: no loader/, io/ or app/.
declare -A allowed=(
  [foundation]=""
  [render]="foundation"
  [lht]="render foundation"
  [loader]="lht render foundation"
  [exporter]="loader lht render foundation"
  [quantize]="foundation"
  [devices]="quantize foundation"
  [io]="foundation"
  [app]="exporter loader lht render devices quantize io foundation"
  [firmware]="devices quantize lht render foundation"
)
layers=(foundation render lht loader exporter quantize devices io app firmware)

# Sub-folder: the sub-folders of the same layer it may include besides
# itself. A file directly in the layer's folder (render/renderer.cpp,
# devices/device_table.cpp) is the layer's top, named by the layer itself.
# devices/*: a device folder uses the shared base (devices/*.hpp) only, never
# another device; only the device table (devices/device_table.cpp) sees all.
declare -A within=(
  [render/solve]=""
  [render/accel]=""
  [render/shapes]="render/solve render/accel"
  [render/scene]="render/shapes render/solve render/accel"
  [render]="render/scene render/shapes render/solve render/accel"
  [lht/grid]=""
  [lht/raster]="lht/grid"
  [lht/table]="lht/raster lht/grid"
  [lht/file]="lht/table lht/raster lht/grid"
  [lht/leaf]="lht/file lht/table lht/raster lht/grid"
  [devices/*]="devices"
  [devices]="devices/*"
  [app/cli]="app"
  [app/term]="app"
  [app/commands]="app/cli app/term app"
  [app]=""
)

# The unit a path belongs to, left in $unit: its layer, or layer/sub-folder
# where the layer has sub-folder rules (every devices/<device>/ folder has).
# Parameter expansion only: no command per include, so the check stays fast.
unit() {
  local top=${1%%/*} rest=${1#*/}
  unit=$top
  if [[ $rest == */* ]] && [[ -n ${within[$top/${rest%%/*}]+x} || $top == devices ]]; then
    unit=$top/${rest%%/*}
  fi
}

# Does rule list $2 allow unit $1? ("devices/*" allows any one device folder.)
allows() {
  local want=$1 entry
  for entry in $2; do
    [[ $entry == "$want" ]] && return 0
    [[ $entry == 'devices/*' && $want == devices/* ]] && return 0
  done
  return 1
}

for layer in "${layers[@]}"; do
  [[ -d $layer ]] || { echo "check-layers.sh: no folder $layer/ (run it in a checkout)" >&2; exit 2; }
done
bad=0 seen=0
while IFS=: read -r file line text; do
  seen=$((seen + 1))
  [[ $text =~ ^#include\ \"([^\"]+)\" ]] || continue
  target=${BASH_REMATCH[1]}
  from_layer=${file%%/*} to_layer=${target%%/*}
  if [[ -z ${allowed[$to_layer]+x} ]]; then
    echo "$file:$line: includes \"$target\", in $to_layer/, a folder that is no layer (add it to scripts/check-layers.sh)"
    bad=1
    continue
  fi
  if [[ $from_layer != "$to_layer" ]]; then
    if ! allows "$to_layer" "${allowed[$from_layer]}"; then
      echo "$file:$line: $from_layer may include ${allowed[$from_layer]:-no other layer}, not $to_layer (\"$target\")"
      bad=1
    fi
    continue
  fi
  unit "$file"; from=$unit
  unit "$target"; to=$unit
  [[ $from == "$to" ]] && continue
  rule=$from
  [[ $from == devices/* ]] && rule='devices/*'
  [[ -n ${within[$rule]+x} ]] || continue
  if ! allows "$to" "${within[$rule]}"; then
    echo "$file:$line: $from may include ${within[$rule]:-nothing else in $from_layer/}, not $to (\"$target\")"
    bad=1
  fi
done < <(grep -rnE '^#include "[a-z0-9_]+/' "${layers[@]}" --include='*.hpp' --include='*.cpp' --include='*.h' || true)

((seen)) || { echo "check-layers.sh: no #include read; nothing was checked" >&2; exit 2; }
if ((bad)); then
  echo "check-layers.sh: an include breaks the allowed edges (scripts/check-layers.sh, docs/architecture.md)" >&2
  exit 1
fi
echo "check-layers.sh: $seen includes in ${#layers[@]} layers and their sub-folders, each on an allowed edge"
