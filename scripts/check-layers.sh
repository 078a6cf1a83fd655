#!/usr/bin/env bash
# The layers point one way (docs/architecture.md): a folder may include headers
# from its own layer and the layers below it, never from a layer above. This
# check reads every #include "folder/..." in the library folders and fails,
# naming file and line, on any include that points up. Run by scripts/test.sh.
#   scripts/check-layers.sh
set -euo pipefail
cd "$(dirname "$0")/.."

# Bottom to top. tests/, bench/ and fuzz/ sit above all of them. firmware/
# (docs/firmware.md) is a top layer beside app/: it may use the layers up to
# devices/ and nothing else (no io/, no app/), and nothing includes it.
layers=(foundation render lht loader exporter quantize devices io app firmware)
declare -A ceiling=([firmware]=devices)

rank() {
  local i
  for i in "${!layers[@]}"; do [[ ${layers[$i]} == "$1" ]] && { echo "$i"; return; }; done
  echo -1
}

bad=0
for layer in "${layers[@]}"; do
  mine=$(rank "$layer")
  while IFS=: read -r file line text; do
    target=$(sed -E 's/.*#include "([a-z0-9_]+)\/.*/\1/' <<<"$text")
    theirs=$(rank "$target")
    if ((theirs < 0)); then
      echo "$file:$line: includes \"$target/...\", a folder that is no layer (add it to scripts/check-layers.sh)"
      bad=1
    elif [[ -n ${ceiling[$layer]:-} && $target != "$layer" ]] && ((theirs > $(rank "${ceiling[$layer]}"))); then
      echo "$file:$line: $layer may include layers up to ${ceiling[$layer]}, not $target"
      bad=1
    elif ((theirs > mine)); then
      echo "$file:$line: $layer (layer $mine) includes $target (layer $theirs), a layer above it; move the shared piece down"
      bad=1
    fi
  done < <(grep -rnE '^#include "[a-z0-9_]+/' "$layer" --include='*.hpp' --include='*.cpp' --include='*.h' || true)
done
if ((bad)); then
  echo "check-layers.sh: layering broken (order, bottom first: ${layers[*]})" >&2
  exit 1
fi
echo "check-layers.sh: ${#layers[@]} layers, no include points up (${layers[*]})"
