#!/usr/bin/env bash
# Builds the page into target/web/ (index.html at its top): the engine for
# wasm32-unknown-unknown, its JavaScript glue by the wasm-bindgen CLI of the crate's exact
# version, the page's files and the bundled point sets with their licence notes. Any static
# file server can serve the folder: `python3 -m http.server -d target/web`.
#
# Needs: `rustup target add wasm32-unknown-unknown` and
# `cargo install wasm-bindgen-cli --version <web/Cargo.toml's wasm-bindgen> --locked`.
set -euo pipefail
cd "$(dirname "$0")/.."

out=target/web
build=target/web-build
version=$(sed -n 's/^wasm-bindgen = "=\(.*\)"/\1/p' web/Cargo.toml)
if [ -z "$version" ]; then
  echo "web/build.sh: web/Cargo.toml pins no exact wasm-bindgen version" >&2
  exit 1
fi
have=$(wasm-bindgen --version 2>/dev/null || true)
if [ "$have" != "wasm-bindgen $version" ]; then
  echo "web/build.sh: needs wasm-bindgen $version (found: ${have:-none}); install it with" >&2
  echo "  cargo install wasm-bindgen-cli --version $version --locked" >&2
  exit 1
fi

CARGO_TARGET_DIR=$build cargo build --release --locked --quiet \
  --manifest-path web/Cargo.toml --target wasm32-unknown-unknown

rm -rf "$out"
mkdir -p "$out/pkg" "$out/examples"
wasm-bindgen --target web --no-typescript --out-dir "$out/pkg" \
  "$build/wasm32-unknown-unknown/release/wdm_crust_web.wasm"
cp web/index.html web/style.css web/app.js web/worker.js "$out/"

# The bundled point sets: bean.txt is the project's own; the others are GPL-3.0 data, which
# travel with the licence text and the READMEs that say where they come from.
cp examples/data/bean.txt examples/data/mushroom.p2d examples/data/crocodile-conf.p2d \
  examples/data/apple_2percent_noise.txt examples/data/Circle0.txt \
  examples/data/GPL-3.0.txt "$out/examples/"
cp examples/data/README.md "$out/examples/README.md"
cp tests/data/hnn-crust-sgp16/ventilator.p2d tests/data/stretchdenoise/data/stair.xy \
  tests/data/stretchdenoise/data/family.p2d "$out/examples/"
cp tests/data/README.md "$out/examples/README-tests-data.md"

wasm=$(wc -c <"$out/pkg/wdm_crust_web_bg.wasm")
js=$(cat "$out/pkg/wdm_crust_web.js" "$out"/*.js | wc -c)
echo "web/build.sh: built $out (wasm $wasm bytes, JavaScript $js bytes)"
