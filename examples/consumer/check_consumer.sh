#!/usr/bin/env bash
# check_consumer.sh BUILD_DIR CONSUMER_SRC SCENE [TUTORIAL_DIR]: install BUILD_DIR into a temporary
# prefix, build the consumer (and, given TUTORIAL_DIR, the tutorial's ex3) against it with
# find_package(stcontact), run them on SCENE at small settings.
set -euo pipefail
build=$1; src=$2; scene=$3; tutorial=${4:+$(realpath "$4")}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
if find "$work/prefix/include" -path '*/src/*' -o -name detail | grep -q .; then
  echo "installed headers hold src/ or detail/:"; find "$work/prefix/include" -path '*/src/*' -o -name detail
  exit 1
fi
cmake -S "$src" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  ${tutorial:+-DSTC_TUTORIAL="$tutorial"} >/dev/null
cmake --build "$work/build" -j2 >/dev/null
"$work/build/consumer" "$scene"
if [ -n "$tutorial" ]; then
  "$work/build/ex3" "$scene" --set mesh.arc_nodes=21 --set time.steps=21 | tail -3
fi
