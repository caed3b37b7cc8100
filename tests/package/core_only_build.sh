#!/usr/bin/env bash
# Lintel::visibility must build with nothing but GLM: configure with LINTEL_CORE_ONLY and check
# that no Vulkan, glTF, CGAL or Embree header reached its compile commands.
set -euo pipefail
source_dir="$1"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cmake -S "$source_dir" -B "$work" -DLINTEL_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=Release >"$work/cfg.log" || { cat "$work/cfg.log"; exit 1; }
cmake --build "$work" --parallel 2 >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
test -f "$work/lib/liblintel_visibility.a"
if grep -rEl 'vulkan|tiny_gltf|CGAL|embree' "$work"/visibility/CMakeFiles/lintel_visibility.dir/ --include='*.d' >/dev/null; then
  echo "visibility depends on a non-GLM library:"; grep -rEl 'vulkan|tiny_gltf|CGAL|embree' "$work"/visibility --include='*.d'; exit 1
fi
echo "core-only build OK"
