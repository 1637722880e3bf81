#!/usr/bin/env bash
# feel as an installed package, the way a game's build uses it (`make test-install`):
#   1. install the build tree into a temporary prefix;
#   2. check libfeel.so: its SONAME, and that it exports the feel_* functions only;
#   3. a C++ consumer with find_package(feel): configure, build and run against the prefix
#      only (feel::feel, feel::engine, feel::c);
#   4. a C program built with pkg-config against libfeel.so;
#   5. Python's ctypes loading libfeel.so, playing a spring on sim:iforce2;
#   6. a parent project with add_subdirectory(feel): only the libraries come along.
# Each consumer checks the spring law on the force the device reports.
#
# usage: scripts/test-install.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: test-install.sh BUILD_DIR}" && pwd)
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/feel-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

step() { printf '\n== %s\n' "$*"; }
fail() { echo "test-install: FAIL: $*" >&2; exit 1; }

step "install into $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
libdir=$(dirname "$(find "$prefix" -name 'libfeel.so' | head -n1)")
[[ -n $libdir && -d $libdir ]] || fail "no libfeel.so under $prefix"
for f in include/feel/feel.h include/feel/version.h include/feel/host/device.hpp bin/feel \
         "${libdir#"$prefix"/}/cmake/feel/feelConfig.cmake" "${libdir#"$prefix"/}/cmake/feel/feelConfigVersion.cmake" \
         "${libdir#"$prefix"/}/pkgconfig/feel.pc" share/doc/feel/c-api.md share/doc/feel/examples/primer.feel.json; do
  [[ -e $prefix/$f ]] || fail "$f was not installed"
done
"$prefix/bin/feel" --version

step "libfeel.so: SONAME and exported symbols"
soname=$(objdump -p "$libdir/libfeel.so" | awk '$1 == "SONAME" {print $2}')
echo "SONAME $soname -> $(readlink "$libdir/libfeel.so")"
[[ $soname =~ ^libfeel\.so\.[0-9]+$ ]] || fail "SONAME is '$soname', expected libfeel.so.N"
# Defined dynamic symbols, without the version node (type A).
exported=$(nm -D --defined-only "$libdir/libfeel.so" | awk '$2 != "A" {print $3}' | sed 's/@.*//')
others=$(grep -v '^feel_' <<<"$exported" || true)
[[ -z $others ]] || fail "libfeel.so exports more than feel_*: $(head -n5 <<<"$others" | tr '\n' ' ')"
echo "$(wc -l <<<"$exported") symbols, all feel_*"

step "C++ consumer: find_package(feel)"
# Only the prefix: no package registry, no system feel, feel's own trees unknown.
cmake -S "$src/tests/install/cpp_consumer" -B "$work/cpp" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
      -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF | tee "$work/cpp-configure.log"
grep -q "feel .* from $prefix/" "$work/cpp-configure.log" || fail "find_package(feel) did not find the prefix's feel"
cmake --build "$work/cpp"
for exe in game firmware c_game; do
  echo "-- $exe"; "$work/cpp/$exe" || fail "the C++ consumer's $exe"
done
if ldd "$work/cpp/c_game" | grep libfeel | grep -v "$prefix" ; then fail "c_game loads a libfeel outside the prefix"; fi

step "C consumer: pkg-config feel"
export PKG_CONFIG_LIBDIR=$libdir/pkgconfig   # the prefix's .pc files only
echo "pkg-config feel $(pkg-config --modversion feel): $(pkg-config --cflags --libs feel)"
cc -std=c11 -Wall -Wextra -Werror -o "$work/c_consumer" "$src/tests/install/c_consumer.c" \
   $(pkg-config --cflags --libs feel) -Wl,-rpath,"$(pkg-config --variable=libdir feel)" -lm
ldd "$work/c_consumer" | grep libfeel
ldd "$work/c_consumer" | grep libfeel | grep -q "$prefix" || fail "c_consumer does not load the prefix's libfeel"
"$work/c_consumer" || fail "the C consumer"

step "Python ctypes"
python3 "$src/tests/install/spring_ctypes.py" "$libdir/libfeel.so" || fail "the ctypes consumer"

step "as a subproject: add_subdirectory(feel) brings its libraries only"
cmake -S "$src/tests/install/subproject" -B "$work/sub" -G Ninja -DFEEL_SOURCE_DIR="$src" \
      -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_rapidcheck=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON \
      >"$work/sub-configure.log" || { cat "$work/sub-configure.log"; fail "configuring a parent of feel"; }
targets=$(ninja -C "$work/sub" -t targets all | sed "s/:.*/:/")
for t in game c_game feel_capi feel_host feel_engine; do
  grep -q "^$t:" <<<"$targets" || fail "the parent has no target $t"
done
if grep -E '^(feel_[a-z_]*test|example_[a-z_]*|feel_bench_[a-z_]*|fuzz_[a-z_]*|feel|feel_render):' <<<"$targets"; then
  fail "a subproject feel builds tests, benchmarks, fuzzers, examples or the CLI"
fi
if grep -q "^CAIRO_\|^pkgcfg_lib_CAIRO" "$work/sub/CMakeCache.txt"; then fail "a subproject feel looks for cairo"; fi
if grep -q "^SNDFILE_\|^pkgcfg_lib_SNDFILE" "$work/sub/CMakeCache.txt"; then fail "a subproject feel looks for libsndfile"; fi
echo "targets: game, c_game and feel's libraries; no tests, benchmarks, fuzzers, examples, CLI or cairo"

echo
echo "test-install: ok (C++ find_package, C pkg-config, Python ctypes, against $prefix)"
