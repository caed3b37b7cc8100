#!/usr/bin/env bash
# Sourced by the package tests: what docs/api.md says is installed, and the check that an install
# prefix holds exactly that. The doc's "Public headers" table is the list (every `*.h` in a row,
# paths under include/lintel/, by component in the first column), so the doc cannot go stale.

# api_headers DOC [COMPONENT...]: the table's headers (of those components; all without), sorted.
api_headers() {
  local doc="$1"; shift
  local wanted=" $* "
  awk '/^## Public headers/ {on = 1; next} on && /^## / {on = 0} on && /^\| *`?[a-z_]+`? *\|/' "$doc" |
    while IFS= read -r row; do
      component="$(cut -d'|' -f2 <<<"$row" | tr -d ' `')"
      [[ "$component" == component ]] && continue
      [[ "$wanted" == "  " || "$wanted" == *" $component "* ]] || continue
      grep -o '`[a-z_/]*\.h`' <<<"$row" | tr -d '`'
    done | sort -u
}

# check_installed_headers PREFIX DOC [COMPONENT...]: the headers under PREFIX/include/lintel are
# exactly the table's (those components' rows); prints the difference and returns 1 otherwise.
check_installed_headers() {
  local prefix="$1" doc="$2"; shift 2
  local installed documented
  installed="$(cd "$prefix/include/lintel" && find . -type f | sed 's|^\./||' | sort)"
  documented="$(api_headers "$doc" "$@")"
  [[ -n "$documented" ]] || { echo "docs/api.md: no headers found in the Public headers table"; return 1; }
  if [[ "$installed" != "$documented" ]]; then
    echo "installed headers differ from docs/api.md's Public headers table (< installed, > documented):"
    diff <(echo "$installed") <(echo "$documented") | grep '^[<>]'
    return 1
  fi
  echo "installed headers match docs/api.md ($(wc -l <<<"$installed") files)"
}

# check_headers_compile_alone SOURCE_DIR PREFIX WORK COMPONENT...: tests/package/header_check.
check_headers_compile_alone() {
  local source_dir="$1" prefix="$2" work="$3"; shift 3
  local components; components="$(IFS=';'; echo "$*")"
  cmake -S "$source_dir/tests/package/header_check" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" \
        -DHEADER_ROOT="$prefix/include" -DLINTEL_COMPONENTS="$components" \
        >"$work.configure.log" 2>&1 || { cat "$work.configure.log"; return 1; }
  cmake --build "$work" --parallel 2 >"$work.build.log" 2>&1 || { cat "$work.build.log"; return 1; }
  echo "every installed header compiles alone ($components)"
}
