#!/usr/bin/env bash
# A plain dependency on the ffvk library (default features) must build none of the tool's
# crates: lists the library's dependency tree as such a dependent gets it and fails, naming
# them, if any is there. Then builds the library that way.
set -euo pipefail
cd "$(dirname "$0")/.."
tool_crates=(clap plotters indicatif ab_glyph serde_json khronos-egl gl_generator)
tree="$(cargo tree -p ffvk --edges normal,build --prefix none --format '{p}')"
found=()
for crate in "${tool_crates[@]}"; do
  if grep -q "^$crate v" <<<"$tree"; then
    found+=("$crate")
  fi
done
if ((${#found[@]})); then
  echo "check-lean-core: a default dependency on ffvk pulls in the tool's crates: ${found[*]}" >&2
  exit 1
fi
echo "check-lean-core: ffvk's default build depends on $(sort -u <<<"$tree" | grep -cv '^ffvk v') crates, none of ${tool_crates[*]}"
cargo build -p ffvk --quiet
# Within the workspace the tool crate turns the library's features on; lint the library as a
# dependent builds it too.
cargo clippy -p ffvk --quiet -- -D warnings
