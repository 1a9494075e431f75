#!/usr/bin/env bash
# check_consumer.sh BUILD_DIR CONSUMER_SRC SCENE: install BUILD_DIR into a temporary prefix,
# build the consumer against it with find_package(stcontact), run it on SCENE.
set -euo pipefail
build=$1; src=$2; scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" -j2 >/dev/null
"$work/build/consumer" "$scene"
