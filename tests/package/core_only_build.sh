#!/usr/bin/env bash
# Lintel::visibility must build with nothing but GLM: configure with LINTEL_CORE_ONLY and check
# that no Vulkan, glTF, CGAL or Embree header reached its compile commands; then install it and
# build tests/package/visibility_consumer against the prefix with every other dependency of Lintel
# disabled (find_package(Lintel COMPONENTS visibility) may need GLM only), and check that the
# prefix holds the visibility component and nothing else: the library, and exactly the headers of
# docs/api.md's visibility row, each compiling alone.
set -euo pipefail
source_dir="$1"
source "$source_dir/tests/package/api_headers.sh"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cmake -S "$source_dir" -B "$work/build" -DLINTEL_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=Release >"$work/cfg.log" || { cat "$work/cfg.log"; exit 1; }
cmake --build "$work/build" --parallel 2 >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
test -f "$work/build/lib/liblintel_visibility.a"
if grep -rEl 'vulkan|tiny_gltf|CGAL|embree' "$work"/build/visibility/CMakeFiles/lintel_visibility.dir/ --include='*.d' >/dev/null; then
  echo "visibility depends on a non-GLM library:"; grep -rEl 'vulkan|tiny_gltf|CGAL|embree' "$work"/build/visibility --include='*.d'; exit 1
fi
echo "core-only build OK"

cmake --install "$work/build" --prefix "$work/prefix" >"$work/install.log"
libs="$(cd "$work/prefix" && find . -name '*.a' | sort)"
[[ "$libs" == "./lib/liblintel_visibility.a" ]] || { echo "core-only install holds more than the core: $libs"; exit 1; }
check_installed_headers "$work/prefix" "$source_dir/docs/api.md" visibility
no_others=(-DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON -DCMAKE_DISABLE_FIND_PACKAGE_TinyGLTF=ON
           -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON)
cmake -S "$source_dir/tests/package/visibility_consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release "${no_others[@]}" >"$work/consumer-cfg.log" 2>&1 || { cat "$work/consumer-cfg.log"; exit 1; }
cmake --build "$work/consumer" >"$work/consumer-build.log" 2>&1 || { cat "$work/consumer-build.log"; exit 1; }
"$work/consumer/visibility_consumer"
echo "find_package(Lintel COMPONENTS visibility) on a core-only prefix OK"
check_headers_compile_alone "$source_dir" "$work/prefix" "$work/headers" visibility
