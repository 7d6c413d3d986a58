#!/usr/bin/env bash
# cmake --install gives a usable package: every header the installed headers include is
# installed, the installed delpsc runs, and examples/embed configures with find_package(delpsc)
# against the temporary prefix (Eigen found through the package's config), builds, runs, and
# prints the same triangulation counts as `delpsc triangulate` on the same points, and meshes the
# sample part (the README's snippet) to the same mesh as `delpsc mesh`. The
# add_subdirectory route is configured too (building it would compile the library a second time).
source "$(dirname "$0")/lib.sh"

BUILD=$(cd "$(dirname "$DELPSC")/.." && pwd)
[[ -f "$BUILD/CMakeCache.txt" ]] || { fail "no CMakeCache.txt above $DELPSC"; finish; exit; }
SOURCE=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$BUILD/CMakeCache.txt")
PREFIX="$TMP/prefix"

# 1. Install; the log lists what went where.
if ! cmake --install "$BUILD" --prefix "$PREFIX" >"$TMP/install.log" 2>&1; then
  fail "cmake --install: $(tail -n 5 "$TMP/install.log")"
  finish; exit
fi
for f in lib/libdelpsc.a lib/cmake/delpsc/delpscConfig.cmake lib/cmake/delpsc/delpscConfigVersion.cmake \
         lib/cmake/delpsc/delpscTargets.cmake bin/delpsc include/delpsc/delaunay/regular_triangulation.h; do
  [[ -f "$PREFIX/$f" ]] && pass || fail "not installed: $f"
done

# 2. Every #include of an installed header that names one of ours resolves inside the prefix.
missing=0
while IFS= read -r header; do
  dir=$(dirname "$header")
  while read -r inc; do
    case "$inc" in
      \"*) target="$dir/${inc:1:-1}" ;;
      \<delpsc/*) target="$PREFIX/include/${inc:1:-1}" ;;
      *) continue ;;
    esac
    [[ -f "$target" ]] || { fail "${header#"$PREFIX"/} includes $inc, not installed"; missing=1; }
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*\([<"][^>"]*[>"]\).*/\1/p' "$header")
done < <(find "$PREFIX/include/delpsc" -name '*.h')
[[ $missing -eq 0 ]] && pass

# 3. The installed command runs.
"$PREFIX/bin/delpsc" --version >"$TMP/version" 2>&1 && grep -q "[0-9]" "$TMP/version" && pass \
  || fail "installed delpsc --version: $(head -c 200 "$TMP/version")"

# 4. examples/embed against the prefix: configure, build, run.
EMBED="$TMP/embed-build"
if ! cmake -S "$SOURCE/examples/embed" -B "$EMBED" -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_BUILD_TYPE=Release \
     >"$TMP/configure.log" 2>&1; then
  fail "configuring examples/embed: $(tail -n 20 "$TMP/configure.log")"
  finish; exit
fi
grep -q "delpsc_DIR:PATH=$PREFIX/lib/cmake/delpsc" "$EMBED/CMakeCache.txt" && pass \
  || fail "examples/embed did not find the installed package: $(grep delpsc_DIR "$EMBED/CMakeCache.txt")"
if ! cmake --build "$EMBED" -j2 >"$TMP/build.log" 2>&1; then
  fail "building examples/embed: $(grep -m 5 -E 'error|Error' "$TMP/build.log")"
  finish; exit
fi

# Random points: the same as delpsc triangulate --generate uniform:1000 --seed 1.
"$EMBED/embed" >"$TMP/out" 2>"$TMP/err" || fail "embed exited $?: $(head -c 300 "$TMP/err")"
embed_cells=$(value finite_cells)
[[ "$(value points)" == "1000" && "$(value vertices)" == "1000" && "$(value valid)" == "true" ]] && pass \
  || fail "embed on random points: $(tr '\n' ' ' <"$TMP/out")"
expect 0 "" -- triangulate --generate uniform:1000 --seed 1
[[ -n "$embed_cells" && "$embed_cells" == "$(value finite_cells)" ]] && pass \
  || fail "finite cells: embed $embed_cells, delpsc triangulate $(value finite_cells)"

# A model: the vertices of the sample part, compared with the same points as a text file.
"$EMBED/embed" "$SOURCE/samples/part.off" >"$TMP/out" 2>"$TMP/err" || fail "embed part.off exited $?"
embed_cells=$(value finite_cells)
[[ "$(value model_vertices)" == "2186" && "$(value vertices)" == "2186" && "$(value valid)" == "true" ]] && pass \
  || fail "embed on the sample part: $(tr '\n' ' ' <"$TMP/out")"
awk 'NR == 2 { n = $1 } NR > 2 && NR <= 2 + n { print $1, $2, $3 }' "$SOURCE/samples/part.off" >"$TMP/part.xyz"
expect 0 "" -- triangulate "$TMP/part.xyz"
[[ -n "$embed_cells" && "$embed_cells" == "$(value finite_cells)" ]] && pass \
  || fail "part finite cells: embed $embed_cells, delpsc triangulate $(value finite_cells)"

# The README's meshing snippet (examples/embed/mesh_model.cpp) against the installed package: the
# same mesh as `delpsc mesh` at the same size, G1 holding, a Medit file written.
"$EMBED/mesh_model" "$SOURCE/samples/part.off" "$TMP/embed.mesh" 0.02 >"$TMP/out" 2>"$TMP/err" \
  || fail "mesh_model exited $?: $(head -c 300 "$TMP/err")"
embed_vertices=$(value vertices)
embed_triangles=$(value triangles)
[[ "$(value g1)" == "true" ]] && grep -q "^Triangles" "$TMP/embed.mesh" && pass || fail "mesh_model: $(tr '\n' ' ' <"$TMP/out")"
expect 0 "" -- mesh "$SOURCE/samples/part.off" -o "$TMP/delpsc.mesh" --size 2% -q
[[ -n "$embed_vertices" && "$embed_vertices" == "$(value vertices)" && "$embed_triangles" == "$(value triangles)" ]] && pass \
  || fail "mesh_model: $embed_vertices vertices, $embed_triangles triangles; delpsc mesh: $(value vertices), $(value triangles)"

# Bad input reaches the embedding program as an io::Error.
"$EMBED/embed" "$TMP/missing.off" >"$TMP/out" 2>"$TMP/err"
[[ $? -eq 2 ]] && grep -q "missing.off" "$TMP/err" && pass || fail "embed on a missing file: $(cat "$TMP/err")"

# 5. add_subdirectory: examples/embed configured on the source tree (the library's own tests,
# benchmarks and command stay off when it is not the top-level project).
if cmake -S "$SOURCE/examples/embed" -B "$TMP/embed-subdir" -DDELPSC_SOURCE_DIR="$SOURCE" \
     >"$TMP/subdir.log" 2>&1; then
  grep -q "^DELPSC_BUILD_TESTS:BOOL=OFF" "$TMP/embed-subdir/CMakeCache.txt" && pass \
    || fail "add_subdirectory turned the library's tests on"
else
  fail "configuring examples/embed with add_subdirectory: $(tail -n 20 "$TMP/subdir.log")"
fi
finish
