#!/bin/sh
# make check-install: mcspec as its users get it. Run from the repository
# root; MAKE, CC, CXX, CMAKE, NM may be set. Everything happens in a
# temporary directory, removed at the end.
#
#  1. make install into a DESTDIR stage: every file in place (SONAME,
#     symlinks, capacities in config.h, mcspec.pc, the CMake package), and
#     make uninstall leaves no file behind.
#  2. make install into a temporary prefix; from then on consumers see only
#     that prefix (no -I or -L into the source tree):
#     - nm: both libraries export exactly the public API (so only mcs_ names);
#     - a C consumer through pkg-config, linked shared and static;
#     - a consumer that links its own float build of KissFFT (the vendored
#       kiss_fft.c, plain names) beside mcspec, shared and static: both right;
#     - a C++17 consumer through find_package(mcspec), shared and static.
#  3. Failures that must happen, with a message that says what to do:
#     - a consumer with -DMCS_MAX_N=256 against the installed headers does
#       not compile; against the source tree's headers it does not link
#       (static, shared, and with --gc-sections);
#     - the same with -DMCS_MAX_SIDE=16 (one of the 2D capacities): it does
#       not compile against the installed headers, and does not link to the
#       build tree's libmcspec.a (BUILD_LIB, default build/libmcspec.a);
#     - the library sources with -ffast-math or -ffinite-math-only, or
#       without the KissFFT configuration, do not compile.
#  4. CMake: the library built with CMake (shared and static, both at
#     MCS_MAX_N = 256 and MCS_MAX_SIDE = 16) and installed exports exactly
#     the API, carries those capacities in mcspec.pc and the package, and
#     serves the C++ consumer; a C consumer takes mcspec by add_subdirectory
#     and by FetchContent.
#  5. The FFTW back end (mk/fft.mk), which must reach static consumers as
#     -lfftw3 (mcspec.pc's Libs.private, the package's link interface):
#     make FFT=fftw install (built once, in build/fftw/, the default build
#     untouched) serves the C consumer through pkg-config, fully static and
#     shared, with mcs_dft_backend() = "fftw3" and the transform right; and
#     the CMake build with -DMCSPEC_FFT=fftw serves the C++ consumer static.
#     Without FFTW (no fftw3.h or libfftw3) these checks fail, saying so.
# Prints one line per check and "N passed, N failed"; exit 1 on any failure.
set -u

: "${MAKE:=make}" "${CC:=cc}" "${CXX:=c++}" "${CMAKE:=cmake}" "${NM:=nm}"
: "${BUILD_LIB:=build/libmcspec.a}"
root=$(pwd)
here=$root/test/consumers
tmp=$(mktemp -d "${TMPDIR:-/tmp}/mcspec-consumers.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
passed=0
failed=0
step=0
cflags="-std=c11 -O2 -Wall -Wextra -Wpedantic"
[ "${WERROR:-}" = 1 ] && cflags="$cflags -Werror"

# check LABEL COMMAND...: passes if COMMAND succeeds; its output is shown on failure.
check() {
    label=$1
    shift
    step=$((step + 1))
    log=$tmp/log.$step
    if "$@" >"$log" 2>&1; then
        passed=$((passed + 1))
        echo "ok   $label"
    else
        failed=$((failed + 1))
        echo "FAIL $label"
        sed 's/^/     | /' "$log" | tail -n 25
    fi
}

# must_fail LABEL PATTERN COMMAND...: passes if COMMAND fails and its output
# contains PATTERN (a fixed string: the message that tells the user what to do).
must_fail() {
    label=$1
    pattern=$2
    shift 2
    step=$((step + 1))
    log=$tmp/log.$step
    if "$@" >"$log" 2>&1; then
        failed=$((failed + 1))
        echo "FAIL $label: it succeeded"
    elif grep -qF -- "$pattern" "$log"; then
        passed=$((passed + 1))
        echo "ok   $label: \"$(grep -F -m1 -- "$pattern" "$log" | sed 's/^[[:space:]]*//' | cut -c1-150)\""
    else
        failed=$((failed + 1))
        echo "FAIL $label: failed without \"$pattern\""
        sed 's/^/     | /' "$log" | tail -n 25
    fi
}

version=$(sed -n 's/^#define MCS_VERSION_STRING "\(.*\)"/\1/p' include/mcspec/version.h)
major=${version%%.*}
case $BUILD_LIB in /*) ;; *) BUILD_LIB=$root/$BUILD_LIB ;; esac

# The default capacities (include/mcspec/config.h), which make install records.
default_caps="-DMCS_MAX_N=4096 -DMCS_MAX_COV_N=64 -DMCS_MAX_FREQ=32 -DMCS_MAX_FREQ_1D=1024 -DMCS_MAX_SIDE=64"
# tag N COV_N FREQ FREQ_1D SIDE: config.h's link-time tag for those capacities.
tag() {
    echo "mcs_config_requires_libmcspec_built_with_MCS_MAX_N_$1_MCS_MAX_COV_N_$2_MCS_MAX_FREQ_$3_MCS_MAX_FREQ_1D_$4_MCS_MAX_SIDE_$5"
}

# ------------------------------------------------------------ 1. stage
stage=$tmp/stage
staged_files() {
    p=$stage/opt/mcspec
    for f in include/mcspec.h include/mcspec/config.h include/mcspec/version.h lib/libmcspec.a \
             "lib/libmcspec.so.$version" lib/pkgconfig/mcspec.pc lib/cmake/mcspec/mcspecConfig.cmake \
             lib/cmake/mcspec/mcspecConfigVersion.cmake share/doc/mcspec/LICENSE \
             share/doc/mcspec/kissfft/COPYING; do
        [ -f "$p/$f" ] || { echo "missing $f"; return 1; }
    done
    for h in "$root"/include/mcspec/*.h; do
        [ -f "$p/include/mcspec/$(basename "$h")" ] || { echo "missing header $(basename "$h")"; return 1; }
    done
    [ "$(readlink "$p/lib/libmcspec.so.$major")" = "libmcspec.so.$version" ] || { echo "bad libmcspec.so.$major"; return 1; }
    [ "$(readlink "$p/lib/libmcspec.so")" = "libmcspec.so.$major" ] || { echo "bad libmcspec.so link"; return 1; }
    readelf -d "$p/lib/libmcspec.so.$version" | grep -q "Library soname: \[libmcspec.so.$major\]" ||
        { echo "SONAME is not libmcspec.so.$major"; return 1; }
    grep -q '^prefix=/opt/mcspec$' "$p/lib/pkgconfig/mcspec.pc" || { echo "mcspec.pc prefix"; return 1; }
    grep -q -- "^Cflags: .*$default_caps\$" "$p/lib/pkgconfig/mcspec.pc" ||
        { echo "mcspec.pc Cflags lack the capacities"; return 1; }
    for c in 'MCS_MAX_N != 4096' 'MCS_MAX_COV_N != 64' 'MCS_MAX_FREQ != 32' 'MCS_MAX_FREQ_1D != 1024' \
             'MCS_MAX_SIDE != 64'; do
        grep -q "$c" "$p/include/mcspec/config.h" || { echo "config.h lacks $c"; return 1; }
    done
    grep -q 'MCS_MAX_N=4096;MCS_MAX_COV_N=64;MCS_MAX_FREQ=32;MCS_MAX_FREQ_1D=1024;MCS_MAX_SIDE=64' \
        "$p/lib/cmake/mcspec/mcspecConfig.cmake" || { echo "mcspecConfig.cmake lacks the capacities"; return 1; }
    grep -q 'set(PACKAGE_VERSION "'"$version"'")' "$p/lib/cmake/mcspec/mcspecConfigVersion.cmake" ||
        { echo "version file"; return 1; }
    echo "all in place"
}
no_files_left() {
    left=$(find "$stage" -type f -o -type l)
    [ -z "$left" ] || { echo "left behind:"; echo "$left"; return 1; }
}
check "make install DESTDIR=... PREFIX=/opt/mcspec" \
    "$MAKE" --no-print-directory install DESTDIR="$stage" PREFIX=/opt/mcspec
check "staged files: headers, libmcspec.a, libmcspec.so.$version (SONAME libmcspec.so.$major), mcspec.pc, CMake package" \
    staged_files
check "make uninstall DESTDIR=... PREFIX=/opt/mcspec" \
    "$MAKE" --no-print-directory uninstall DESTDIR="$stage" PREFIX=/opt/mcspec
check "make uninstall leaves no file" no_files_left

# ------------------------------------------------------------ 2. installed
prefix=$tmp/prefix
libdir=$prefix/lib
check "make install PREFIX=<tmp>" "$MAKE" --no-print-directory install PREFIX="$prefix"
export PKG_CONFIG_PATH="$libdir/pkgconfig"
pc_cflags=$(pkg-config --cflags mcspec)
pc_libs=$(pkg-config --libs mcspec)
pc_libs_L=$(pkg-config --libs-only-L mcspec)
echo "     pkg-config --cflags mcspec: $pc_cflags"

only_mcs_exported() {
    "$NM" -g --defined-only -P "$libdir/libmcspec.a" | awk 'NF >= 2 && $1 !~ /:$/ && $1 !~ /^mcs_/' >"$tmp/foreign.a"
    "$NM" -D --defined-only -P "$libdir/libmcspec.so" | awk 'NF >= 2 && $1 !~ /^mcs_/' >"$tmp/foreign.so"
    cat "$tmp/foreign.a" "$tmp/foreign.so"
    [ ! -s "$tmp/foreign.a" ] && [ ! -s "$tmp/foreign.so" ]
}
check "nm: libmcspec.a and libmcspec.so export no symbol without the mcs_ prefix" only_mcs_exported
check "nm: both export exactly the API of the installed headers" \
    sh tools/check_api.sh -c "$CC $pc_cflags" -d "$prefix/include" -n "$NM" \
        -p tools/api_pending.txt "$libdir/libmcspec.a" "$libdir/libmcspec.so"

links_shared() { readelf -d "$1" | grep -q "Shared library: \[libmcspec.so.$major\]"; }
links_static() { ! readelf -d "$1" | grep -q 'libmcspec'; }

build_c_shared() {
    # shellcheck disable=SC2086 # flag lists
    $CC $cflags $pc_cflags -DEXPECT_DFT_BACKEND=kissfft "$here/consumer.c" -o "$tmp/c_shared" $pc_libs -Wl,-rpath,"$libdir" -lm &&
        links_shared "$tmp/c_shared" && "$tmp/c_shared"
}
build_c_static() {
    # shellcheck disable=SC2086
    $CC $cflags $pc_cflags -DEXPECT_DFT_BACKEND=kissfft "$here/consumer.c" -o "$tmp/c_static" $pc_libs_L -Wl,-Bstatic -lmcspec \
        -Wl,-Bdynamic -lm && links_static "$tmp/c_static" && "$tmp/c_static"
}
check "C consumer, pkg-config, shared (NEEDED libmcspec.so.$major)" build_c_shared
check "C consumer, pkg-config, static" build_c_static

# The renderer's own KissFFT: float, plain names, malloc allowed.
kiss_float() {
    $CC -std=c11 -O2 -Dkiss_fft_scalar=float -I"$root/src/vendor/kissfft" \
        -c "$root/src/vendor/kissfft/kiss_fft.c" -o "$tmp/kiss_fft_float.o"
}
build_kiss() {
    kind=$1
    if [ "$kind" = shared ]; then libs="$pc_libs -Wl,-rpath,$libdir"; else libs="$pc_libs_L -Wl,-Bstatic -lmcspec -Wl,-Bdynamic"; fi
    # shellcheck disable=SC2086
    kiss_float && $CC $cflags $pc_cflags -I"$root/src/vendor/kissfft" -Dkiss_fft_scalar=float \
        "$here/kissfloat.c" "$tmp/kiss_fft_float.o" -o "$tmp/kiss_$kind" $libs -lm &&
        "$tmp/kiss_$kind"
}
check "consumer with its own float KissFFT, shared: both transforms right" build_kiss shared
check "consumer with its own float KissFFT, static: both transforms right" build_kiss static

build_cxx() {
    dir=$1
    pfx=$2
    shift 2
    "$CMAKE" -S "$here/cxx" -B "$dir" -DCMAKE_PREFIX_PATH="$pfx" -DCMAKE_CXX_COMPILER="$CXX" "$@" &&
        "$CMAKE" --build "$dir" && "$dir/cxx_consumer"
}
cxx_shared() { build_cxx "$tmp/cxx_shared" "$prefix" && links_shared "$tmp/cxx_shared/cxx_consumer"; }
cxx_static() { build_cxx "$tmp/cxx_static" "$prefix" -DMCSPEC_USE_STATIC=ON && links_static "$tmp/cxx_static/cxx_consumer"; }
check "C++17 consumer, find_package(mcspec 0.2), mcspec::mcspec shared" cxx_shared
check "C++17 consumer, find_package(mcspec 0.2), mcspec::mcspec static" cxx_static

# ------------------------------------------------------------ 3. must fail
# shellcheck disable=SC2086
must_fail "consumer with -DMCS_MAX_N=256 against the installed headers (4096) does not compile" \
    "built with MCS_MAX_N=4096" \
    $CC $cflags -DMCS_MAX_N=256 -I"$prefix/include" -c "$here/consumer.c" -o "$tmp/mismatch.o"
tag256=$(tag 256 64 32 1024 64)
# shellcheck disable=SC2086
must_fail "consumer with -DMCS_MAX_N=256 (source-tree headers) does not link to the installed libmcspec.a" \
    "undefined reference to \`$tag256'" \
    $CC $cflags -DMCS_MAX_N=256 -I"$root/include" "$here/consumer.c" -o "$tmp/mismatch_static" \
        $pc_libs_L -Wl,-Bstatic -lmcspec -Wl,-Bdynamic -lm
# shellcheck disable=SC2086
must_fail "... nor to the installed libmcspec.so" "undefined reference to \`$tag256'" \
    $CC $cflags -DMCS_MAX_N=256 -I"$root/include" "$here/consumer.c" -o "$tmp/mismatch_shared" \
        $pc_libs_L -lmcspec -lm
# shellcheck disable=SC2086
must_fail "... nor with -ffunction-sections -fdata-sections -Wl,--gc-sections" \
    "undefined reference to \`$tag256'" \
    $CC $cflags -ffunction-sections -fdata-sections -DMCS_MAX_N=256 -I"$root/include" \
        "$here/consumer.c" -o "$tmp/mismatch_gc" -Wl,--gc-sections $pc_libs_L -Wl,-Bstatic -lmcspec \
        -Wl,-Bdynamic -lm
# One of the capacities added with the point-set and 2D modules, against
# the installed headers and against the build tree's archive.
# shellcheck disable=SC2086
must_fail "consumer with -DMCS_MAX_SIDE=16 against the installed headers (64) does not compile" \
    "built with MCS_MAX_SIDE=64" \
    $CC $cflags -DMCS_MAX_SIDE=16 -I"$prefix/include" -c "$here/consumer.c" -o "$tmp/mismatch_side.o"
# shellcheck disable=SC2086
must_fail "consumer with -DMCS_MAX_SIDE=16 (source-tree headers) does not link to the build tree's libmcspec.a" \
    "undefined reference to \`$(tag 4096 64 32 1024 16)'" \
    $CC $cflags -DMCS_MAX_SIDE=16 -I"$root/include" "$here/consumer.c" -o "$tmp/mismatch_side" \
        "$BUILD_LIB" -lm
must_fail "library sources with -ffast-math do not compile" "do not compile the library with -ffast-math" \
    "$MAKE" --no-print-directory BUILD="$tmp/fastmath" CFLAGS=-ffast-math "$tmp/fastmath/libmcspec.a"
must_fail "library sources with -ffinite-math-only do not compile" "do not compile the library with -ffast-math" \
    "$MAKE" --no-print-directory BUILD="$tmp/finite" CFLAGS=-ffinite-math-only "$tmp/finite/libmcspec.a"
glob_build() {
    mkdir -p "$tmp/glob" && cd "$tmp/glob" &&
        $CC -std=c11 -I"$root/include" -I"$root/src/vendor/kissfft" -I"$root/src" -c $(ls "$root"/src/*/*.c | grep -v /vendor/)
}
must_fail "library sources compiled as a glob without the KissFFT configuration do not compile" \
    "compile src/*/*.c (not src/vendor/) and src/vendor/kissfft/kiss_fft.c with the KissFFT configuration" glob_build
cd "$root" || exit 1

# ------------------------------------------------------------ 4. CMake
cmprefix=$tmp/cmprefix
cmake_lib() {
    dir=$1
    shift
    "$CMAKE" -S "$root" -B "$dir" -DCMAKE_C_COMPILER="$CC" -DCMAKE_INSTALL_PREFIX="$cmprefix" \
        -DMCSPEC_WERROR="${WERROR:-OFF}" "$@" &&
        "$CMAKE" --build "$dir" && "$CMAKE" --install "$dir"
}
check "CMake: libmcspec shared, MCSPEC_MAX_N=256 MCSPEC_MAX_SIDE=16, built and installed" \
    cmake_lib "$tmp/cm_shared" -DBUILD_SHARED_LIBS=ON -DMCSPEC_MAX_N=256 -DMCSPEC_MAX_SIDE=16
check "CMake: libmcspec static, MCSPEC_MAX_N=256 MCSPEC_MAX_SIDE=16, built and installed" \
    cmake_lib "$tmp/cm_static" -DBUILD_SHARED_LIBS=OFF -DMCSPEC_MAX_N=256 -DMCSPEC_MAX_SIDE=16
# No CMAKE_BUILD_TYPE: the library's objects still get -O2 (CMake's default
# flags are -O0); a named build type keeps its own flags.
cm_flags() {
    dir=$1
    shift
    "$CMAKE" -S "$root" -B "$dir" -DCMAKE_C_COMPILER="$CC" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "$@" \
        >/dev/null && grep '"command".*src/core/status.c' "$dir/compile_commands.json"
}
cm_default_opt() { cm_flags "$tmp/cm_default" | grep -q -- ' -O2 '; }
cm_debug_opt() { ! cm_flags "$tmp/cm_debug" -DCMAKE_BUILD_TYPE=Debug | grep -q -- ' -O2 '; }
check "CMake with no build type compiles the library with -O2" cm_default_opt
check "CMake with CMAKE_BUILD_TYPE=Debug keeps its own flags (no -O2 added)" cm_debug_opt
cm_so=$cmprefix/lib/libmcspec.so.$version
check "CMake: libmcspec.so.$version has SONAME libmcspec.so.$major" \
    sh -c "readelf -d '$cm_so' | grep -q 'Library soname: \[libmcspec.so.$major\]'"
check "CMake: both libraries export exactly the API of the installed headers" \
    sh tools/check_api.sh -c "$CC -I$cmprefix/include" -d "$cmprefix/include" -n "$NM" \
        -p tools/api_pending.txt "$cmprefix/lib/libmcspec.a" "$cm_so"
cm_caps="-DMCS_MAX_N=256 -DMCS_MAX_COV_N=64 -DMCS_MAX_FREQ=32 -DMCS_MAX_FREQ_1D=1024 -DMCS_MAX_SIDE=16"
check "CMake: installed mcspec.pc carries all five capacities ($cm_caps)" \
    sh -c "PKG_CONFIG_PATH='$cmprefix/lib/pkgconfig' pkg-config --cflags mcspec | grep -q -- '$cm_caps'"
cm_expect="-DEXPECT_MAX_N=256 -DEXPECT_MAX_SIDE=16"
# shellcheck disable=SC2086
cxx_cm() { build_cxx "$tmp/cxx_cm" "$cmprefix" $cm_expect && links_shared "$tmp/cxx_cm/cxx_consumer"; }
# shellcheck disable=SC2086
cxx_cm_static() { build_cxx "$tmp/cxx_cm_static" "$cmprefix" $cm_expect -DMCSPEC_USE_STATIC=ON; }
check "C++17 consumer against the CMake install (shared, 256, side 16)" cxx_cm
check "C++17 consumer against the CMake install (static, 256, side 16)" cxx_cm_static

subdir() {
    dir=$1
    shift
    "$CMAKE" -S "$here/subdir" -B "$dir" -DCMAKE_C_COMPILER="$CC" -DMCSPEC_SOURCE_DIR="$root" "$@" &&
        "$CMAKE" --build "$dir" && "$dir/subdir_consumer"
}
check "C consumer, add_subdirectory(mcspec)" subdir "$tmp/subdir"
check "C consumer, FetchContent(mcspec), MCSPEC_MAX_N=256 MCSPEC_MAX_SIDE=16 shared" \
    subdir "$tmp/fetch" -DUSE_FETCHCONTENT=ON -DMCSPEC_MAX_N=256 -DEXPECT_MAX_N=256 \
        -DMCSPEC_MAX_SIDE=16 -DEXPECT_MAX_SIDE=16 -DBUILD_SHARED_LIBS=ON

# ------------------------------------------------------------ 5. FFTW
fftwprefix=$tmp/fftwprefix
cmfftw=$tmp/cmfftw
have_fftw=$(sh tools/bench_deps.sh fftw "$CC")
need_fftw() {
    [ "$have_fftw" = 1 ] ||
        { echo "no FFTW 3: $CC cannot build a program with <fftw3.h> and -lfftw3 (install libfftw3-dev)"; return 1; }
}
# The default build's tree (that of BUILD_LIB) is not written to: FFT=fftw
# builds in its fftw/ subdirectory.
fftw_install() {
    need_fftw || return 1
    bdir=$(dirname "$BUILD_LIB")
    touch "$tmp/fftw.stamp"
    "$MAKE" --no-print-directory FFT=fftw install PREFIX="$fftwprefix" || return 1
    touched=$(find "$bdir" -path "$bdir/fftw" -prune -o -type f -newer "$tmp/fftw.stamp" -print)
    [ -z "$touched" ] || { echo "the default build was written to:"; echo "$touched"; return 1; }
}
# fftw_package PREFIX: -lfftw3 in mcspec.pc's Libs.private (and not Libs);
# fftw3 in the package's link interface of the archive, before m (which
# libfftw3.a calls: a C consumer linked -static needs that order; the C++
# consumer cannot show it, as g++ puts -lm at the end of every link).
fftw_package() {
    need_fftw || return 1
    pc=$1/lib/pkgconfig/mcspec.pc
    grep '^Libs' "$pc"
    grep -q '^Libs.private:.* -lfftw3' "$pc" || { echo "mcspec.pc: no -lfftw3 in Libs.private"; return 1; }
    ! grep -q '^Libs:.*fftw' "$pc" || { echo "mcspec.pc: fftw3 in Libs"; return 1; }
    grep -q '^set(_mcspec_static_libs fftw3 m)' "$1/lib/cmake/mcspec/mcspecConfig.cmake" ||
        { echo "mcspecConfig.cmake: the archive's link libraries are not fftw3 then m"; return 1; }
}
# Fully static (libmcspec.a, libfftw3.a, libm.a): the flags pkg-config gives
# must name every library, in an order that resolves.
fftw_c_static() {
    need_fftw || return 1
    # shellcheck disable=SC2046,SC2086
    $CC $cflags -static -DEXPECT_DFT_BACKEND=fftw3 "$here/consumer.c" -o "$tmp/fftw_static" \
        $(PKG_CONFIG_PATH="$fftwprefix/lib/pkgconfig" pkg-config --static --cflags --libs mcspec) &&
        ! readelf -d "$tmp/fftw_static" | grep -q NEEDED && "$tmp/fftw_static"
}
fftw_c_shared() {
    need_fftw || return 1
    # shellcheck disable=SC2046,SC2086
    $CC $cflags -DEXPECT_DFT_BACKEND=fftw3 "$here/consumer.c" -o "$tmp/fftw_shared" \
        $(PKG_CONFIG_PATH="$fftwprefix/lib/pkgconfig" pkg-config --cflags --libs mcspec) \
        -Wl,-rpath,"$fftwprefix/lib" -lm &&
        links_shared "$tmp/fftw_shared" && "$tmp/fftw_shared"
}
fftw_cmake_lib() {
    need_fftw || return 1
    "$CMAKE" -S "$root" -B "$tmp/cm_fftw" -DCMAKE_C_COMPILER="$CC" -DCMAKE_INSTALL_PREFIX="$cmfftw" \
        -DMCSPEC_WERROR="${WERROR:-OFF}" -DMCSPEC_FFT=fftw -DBUILD_SHARED_LIBS=OFF &&
        "$CMAKE" --build "$tmp/cm_fftw" && "$CMAKE" --install "$tmp/cm_fftw"
}
fftw_cxx_static() {
    need_fftw || return 1
    build_cxx "$tmp/cxx_fftw" "$cmfftw" -DMCSPEC_USE_STATIC=ON -DEXPECT_DFT_BACKEND=fftw3 &&
        links_static "$tmp/cxx_fftw/cxx_consumer"
}
check "make FFT=fftw install PREFIX=<tmp2> (in build/fftw/, the default build untouched)" fftw_install
check "FFT=fftw install: -lfftw3 in mcspec.pc's Libs.private (not Libs) and the package's archive link" \
    fftw_package "$fftwprefix"
check "C consumer, pkg-config --static, linked -static: back end fftw3, transform right" fftw_c_static
check "C consumer, pkg-config, shared (NEEDED libmcspec.so.$major): back end fftw3, transform right" \
    fftw_c_shared
check "CMake: libmcspec static, MCSPEC_FFT=fftw, built and installed" fftw_cmake_lib
check "CMake FFTW install: -lfftw3 in mcspec.pc's Libs.private (not Libs) and the package's archive link" \
    fftw_package "$cmfftw"
check "C++17 consumer against the CMake FFTW install (static): back end fftw3, transform right" \
    fftw_cxx_static

echo "check-install: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
