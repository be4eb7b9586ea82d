#!/usr/bin/env bash
# The two commands of the README:
#   ./run.sh audit  the robustness audit: stability and speed-accuracy for every query family,
#                   and the scene audit of the Stanford bunny; writes audit-report/report.html
#   ./run.sh test   the whole test suite: release build and tests (oracle, static, consumer,
#                   benchmark smoke, audit output and report in Chromium), then the ASan+UBSan
#                   build: its tests, and each fuzzer's corpus replay and a fixed-time run
# and ./run.sh demo: the tiers on touching cases + a speed table, in the terminal; ./run.sh bench
# [benchmark flags]: the optimised benchmarks, a table in the terminal and every timing in bench.json;
# ./run.sh oracle [scale] [Catch2 test spec]: the oracle tests with their case counts times the scale
# (default 20), one test program after another, each log in build/oracle-runs.
# All install what is missing first (Debian bookworm + bookworm-backports) and skip what is there.
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages, and the backports suite for the two that need newer versions.
# clang-format-19 checks the formatting (format_check), python3-matplotlib draws the audit report, python3-jsonschema and chromium test it, libcgal-demo
# has the real meshes (data.tar.gz), libqhull-dev is the convex-hull peer in the bounding-volume table, libeigen3-dev lets CGAL's
# oriented_bounding_box be the OBB peer, libfcl-dev is the FCL peer in the OBB-OBB and triangle-triangle benchmarks,
# libhwy-dev (Google Highway) is the batches' SIMD with run-time dispatch, libembree-dev (Embree 3) the ray-casting peer in the scene benchmarks.
packages=(clang-19 clang-tools-19 clang-format-19 libclang-rt-19-dev libfuzzer-19-dev ninja-build libboost-dev libgmp-dev
          libmpfr-dev libcgal-dev libcgal-demo libqhull-dev libeigen3-dev libfcl-dev libhwy-dev libembree-dev libbenchmark-dev python3 python3-matplotlib python3-jsonschema
          chromium)
backports=(cmake catch2)

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
version_ok() { # package, minimum version
    local v; v=$(dpkg-query -W -f='${Version}' "$1" 2>/dev/null || true)
    [ -n "$v" ] && dpkg --compare-versions "$v" ge "$2"
}

setup() {
    local missing=() from_backports=()
    for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
    version_ok cmake 3.30 || from_backports+=(cmake)
    version_ok catch2 3.0 || from_backports+=(catch2)
    if [ ${#missing[@]} -eq 0 ] && [ ${#from_backports[@]} -eq 0 ]; then
        echo "setup: every dependency is installed"
        return
    fi
    echo "setup: installing ${missing[*]} ${from_backports[*]}"
    if [ ${#from_backports[@]} -gt 0 ] && ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
        echo "deb http://deb.debian.org/debian bookworm-backports main" | as_root tee /etc/apt/sources.list.d/bookworm-backports.list >/dev/null
    fi
    as_root apt-get update -qq || echo "setup: apt-get update reported errors (a third-party source?); continuing"
    export DEBIAN_FRONTEND=noninteractive
    if [ ${#missing[@]} -gt 0 ]; then as_root apt-get install -y -qq "${missing[@]}" >/dev/null; fi
    if [ ${#from_backports[@]} -gt 0 ]; then as_root apt-get install -y -qq -t bookworm-backports "${from_backports[@]}" >/dev/null; fi
}

# Real meshes from Debian's libcgal-demo, unpacked into build/data/meshes (never committed).
meshes=(bunny00 armadillo elephant fandisk ChineseDragon-10kv)
data() {
    local archive=/usr/share/doc/libcgal-dev/data.tar.gz missing=()
    for m in "${meshes[@]}"; do [ -s "build/data/meshes/$m.off" ] || missing+=("data/meshes/$m.off"); done
    [ ${#missing[@]} -eq 0 ] && return
    mkdir -p build
    tar -xzf "$archive" -C build "${missing[@]}"
}

build() { # preset [cache settings...]
    cmake --preset "$1" -Wno-dev "${@:2}" >/dev/null
    cmake --build --preset "$1"
}

total_passed=0
total_failed=0
run_tests() { # preset [ctest args...]: prints every "[cases]" line and the summary
    local preset=$1; shift
    local log="build/$preset/ctest.log" rc=0
    ctest --preset "$preset" -V "$@" >"$log" 2>&1 || rc=$?
    local summary
    summary=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$log" | tail -1 || true)
    if [[ $summary =~ ([0-9]+)\ tests\ failed\ out\ of\ ([0-9]+) ]]; then
        total_failed=$(( total_failed + BASH_REMATCH[1] ))
        total_passed=$(( total_passed + BASH_REMATCH[2] - BASH_REMATCH[1] ))
    fi
    grep -E "\[cases\]|replayed [0-9]+ inputs|Done [0-9]+ runs|^[0-9]+% tests passed" "$log" | sed -E "s/^[0-9]+: //" || true
    if [ $rc -ne 0 ]; then
        echo "---- failures (full log: $log) ----"
        grep -E "\*\*\*Failed|\*\*\*Exception|FAILED|Timeout" "$log" | head -50 || true
        ctest --preset "$preset" --rerun-failed --output-on-failure 2>&1 | tail -120 || true
        exit $rc
    fi
}

case "${1:-}" in
audit)
    setup
    data
    cmake --preset release -Wno-dev >/dev/null
    cmake --build --preset release --target incidence_audit
    ./build/release/tools/audit/incidence-audit all --scene build/data/meshes/bunny00.off --out audit-report
    echo "open $(pwd)/audit-report/report.html in a browser"
    ;;
demo)
    setup
    build release
    ./build/release/tools/demo/incidence_demo
    ;;
bench)
    setup
    data
    cmake --preset release -Wno-dev >/dev/null
    cmake --build --preset release --target incidence_bench
    ./build/release/bench/incidence_bench --benchmark_out=bench.json --benchmark_out_format=json "${@:2}"
    echo "timings in $(pwd)/bench.json"
    ;;
test)
    setup
    data
    start=$(date +%s)
    echo "== release build: unit, oracle, static, consumer-from-install, benchmark smoke"
    build release
    run_tests release
    echo "== debug build (-O0) with AddressSanitizer + UndefinedBehaviorSanitizer: the tests (the oracle tests of"
    echo "   one pair per shared body, on a twentieth of the cases), then each libFuzzer harness: corpus"
    echo "   replay and a fixed-time run"
    build debug -DINCIDENCE_ORACLE_ARCHIVE="$(pwd)/build/release/testkit/oracle/libincidence_oracle.a" # the same uninstrumented oracle, built once
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 run_tests debug -E consumer_from_install
    echo "== all suites passed in $(( $(date +%s) - start )) s"
    echo "$total_passed passed, $total_failed failed"
    ;;
oracle)
    # The oracle tests with more cases than the suite's: every release test program's tests that
    # match the Catch2 spec (default: tagged [oracle]), each case count times the scale (default 20).
    setup
    data
    build release
    scale=${2:-20}
    spec=${3:-[oracle]}
    start=$(date +%s)
    failed=()
    mkdir -p build/oracle-runs
    for t in build/release/tests/test_*; do
        [ -f "$t" ] && [ -x "$t" ] || continue
        "$t" --list-tests "$spec" | grep -q "^0 matching test cases" && continue
        log="build/oracle-runs/$(basename "$t").log" t0=$(date +%s) rc=0
        INCIDENCE_CASES_SCALE=$scale "$t" "$spec" --skip-benchmarks >"$log" 2>&1 || rc=$?
        grep -E "\[cases\]" "$log" || true
        echo "== $(basename "$t"): exit $rc in $(( $(date +%s) - t0 )) s (log: $log)"
        [ $rc -eq 0 ] || failed+=("$(basename "$t")")
    done
    echo "== oracle tests at scale $scale done in $(( $(date +%s) - start )) s; failed: ${failed[*]:-none}"
    [ ${#failed[@]} -eq 0 ]
    ;;
*)
    echo "usage: $0 audit | test | demo | bench [benchmark flags] | oracle [scale] [Catch2 test spec]" >&2
    exit 2
    ;;
esac
