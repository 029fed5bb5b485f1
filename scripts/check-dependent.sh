#!/usr/bin/env bash
# Proves that a crate outside this repository can depend on ffvk's core: copies
# tests/dependent to a temporary folder (so none of this repository's Cargo configuration
# applies), points its path dependency at this checkout, builds it and runs it on lavapipe.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp -r "$repo/tests/dependent/." "$work/"
# The workspace's lockfile: the dependent resolves the same crate versions ffvk is tested with
# (cargo drops the workspace's own entries and adds the dependent's).
cp "$repo/Cargo.lock" "$work/"
sed -i "s|FFVK_PATH|$repo/ffvk|" "$work/Cargo.toml"
# Its own target folder under ours, so later runs reuse the build.
export CARGO_TARGET_DIR="$repo/target/dependent"
cd "$work"
cargo run --quiet
