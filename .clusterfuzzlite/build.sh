#!/bin/bash -eu
# Builds every fuzz target of the kit into $OUT the way ClusterFuzzLite /
# OSS-Fuzz expects (docs/FUZZING.md):
#   fuzz_deframer, fuzz_broadcast   C, libFuzzer ($CC $CFLAGS $LIB_FUZZING_ENGINE)
#   fuzz_decode                     Python, atheris (compile_python_fuzzer)
#   fuzz_go_decode_stream           Go, FuzzDecodeStream (compile_native_go_fuzzer)
# each with <name>_seed_corpus.zip from the golden vectors (tools/fuzz_corpus.py).
#
# Outside the builder image the same script builds the C targets with the
# local clang (the Python and Go helpers exist only in the image; their
# targets are then skipped, and the Go copy is only compiled):
#   SRC=$PWD OUT=/tmp/cfl CC=clang-14 CXX=clang++-14 \
#   CFLAGS="-O1 -g -fsanitize=address,undefined -fsanitize=fuzzer-no-link" \
#   LIB_FUZZING_ENGINE=-fsanitize=fuzzer PYTHON=.venv/bin/python .clusterfuzzlite/build.sh

# The image copies the repository to $SRC/osdk-conformance; a local run
# passes the repository itself as $SRC.
if [ -d "$SRC/osdk-conformance" ]; then ROOT=$SRC/osdk-conformance; else ROOT=$SRC; fi
ROOT=$(cd "$ROOT" && pwd)
OUT=$(mkdir -p "$OUT" && cd "$OUT" && pwd)
WORK=${WORK:-$(mktemp -d)}
SANITIZER=${SANITIZER:-address}
PYTHON=${PYTHON:-python3}
CXX=${CXX:-$CC}
CXXFLAGS=${CXXFLAGS:-$CFLAGS}
cd "$ROOT"

if [ ! -x "$(command -v compile_python_fuzzer || true)" ]; then
    PY_ENGINE=""
else
    PY_ENGINE=yes
    # the kit and its pinned dependencies, as a normal install: PyInstaller
    # follows imports from site-packages
    pip3 install --quiet -c constraints.txt .
fi

seeds() {  # seeds TARGET NAME [fuzz_corpus options]: $OUT/NAME_seed_corpus.zip
    local dir=$WORK/seeds/$2
    rm -rf "$dir" && mkdir -p "$dir"
    "$PYTHON" tools/fuzz_corpus.py "$1" "$dir" "${@:3}"
    rm -f "$OUT/$2_seed_corpus.zip"
    (cd "$dir" && zip -q -r "$OUT/$2_seed_corpus.zip" .)
}

# ---- C: the generated decoder (generated/c) under libFuzzer
objs=()
for src in generated/c/*.c; do
    obj=$WORK/c/$(basename "${src%.c}").o
    mkdir -p "$WORK/c"
    $CC $CFLAGS -std=c99 -Igenerated/c -c "$src" -o "$obj"
    objs+=("$obj")
done
for target in deframer broadcast; do
    $CC $CFLAGS -std=c99 -Igenerated/c -c "conformance/testees/c/fuzz/fuzz_$target.c" -o "$WORK/c/fuzz_$target.o"
    $CXX $CXXFLAGS "$WORK/c/fuzz_$target.o" "${objs[@]}" $LIB_FUZZING_ENGINE -o "$OUT/fuzz_$target"
    seeds "$target" "fuzz_$target"
    echo "build.sh: built fuzz_$target"
done

# atheris and Go fuzzing have an address (and coverage) build only.
if [ "$SANITIZER" != address ] && [ "$SANITIZER" != coverage ]; then
    echo "build.sh: SANITIZER=$SANITIZER: the Python and Go targets are built in the address build only"
    exit 0
fi

# ---- Python: fuzz/fuzz_decode.py under atheris
if [ -n "$PY_ENGINE" ]; then
    # The kit reads spec/ and the vector schema at run time, from the
    # directory above its package (osdk_conformance/core/paths.py): in the bundle,
    # next to it.
    compile_python_fuzzer fuzz/fuzz_decode.py --paths tools --paths conformance/testees \
        --add-data "spec:spec" --add-data "vectors/vectors.schema.json:vectors"
    seeds deframer fuzz_decode
    echo "build.sh: built fuzz_decode"
else
    echo "build.sh: compile_python_fuzzer not found (not the builder image): fuzz_decode skipped"
fi

# ---- Go: FuzzDecodeStream of the Go testee
# go-118-fuzz-build imports the package of the fuzz function, and the
# testee is package main, which cannot be imported: build from a copy of
# its sources renamed to package ossfuzz (its func main is then an ordinary
# function), in a copy of its module whose generated-parser replace points
# back here.
gomod=$WORK/go-module
rm -rf "$gomod" && mkdir -p "$gomod/ossfuzz"
cp conformance/testees/go/go.mod conformance/testees/go/go.sum "$gomod/"
(cd "$gomod" && go mod edit -replace "osdk-conformance.local/generated/go=$ROOT/generated/go")
for src in conformance/testees/go/*.go; do
    case $(basename "$src") in
        *_test.go) [ "$(basename "$src")" = fuzz_test.go ] || continue ;;
    esac
    sed 's/^package main$/package ossfuzz/' "$src" > "$gomod/ossfuzz/$(basename "$src")"
done
if [ -x "$(command -v compile_native_go_fuzzer || true)" ]; then
    (cd "$gomod" && compile_native_go_fuzzer osdk-conformance.local/testees/go/ossfuzz FuzzDecodeStream fuzz_go_decode_stream)
    # the testee finds its tables above its executable (tables.go tablesPath)
    mkdir -p "$OUT/generated/tables"
    cp generated/tables/osdk_tables.json "$OUT/generated/tables/"
    seeds deframer fuzz_go_decode_stream --length-prefix
    echo "build.sh: built fuzz_go_decode_stream"
else
    (cd "$gomod" && go vet ./ossfuzz)
    echo "build.sh: compile_native_go_fuzzer not found (not the builder image): fuzz_go_decode_stream skipped" \
         "(its package copy compiles)"
fi
