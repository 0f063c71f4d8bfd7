#!/bin/sh
# fuzz.sh -- `make fuzz`: the libFuzzer targets of tests/fuzz/ side by side.
#
#   FUZZ_SECONDS=300 sh scripts/fuzz.sh
#
# Installs clang and its fuzzer runtime with apt-get when a trivial
# fuzzer does not link (root needed; otherwise prints the command), builds
# build/fuzz/fuzz_readers and build/fuzz/fuzz_ops (make fuzz-build), runs
# both for FUZZ_SECONDS each at the same time on the seeds of
# tests/fuzz-corpus/ (new inputs go to build/fuzz/corpus-*, not to git),
# and copies every crash, leak, timeout or out-of-memory input into
# tests/fuzz-corpus/TARGET/, where test_fuzz_replay replays it in make
# test.  Ends with "fuzz: E executions, C crashes"; exits 1 on a crash.
set -u
secs=${FUZZ_SECONDS:-300}
cc=${FUZZ_CC:-clang}
out=build/fuzz

toolchain_ok() {
    d=$(mktemp -d)
    printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n);\nint LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' >"$d/t.c"
    "$cc" -fsanitize=fuzzer,address,undefined "$d/t.c" -o "$d/t" >/dev/null 2>&1
    rc=$?
    rm -rf "$d"
    return $rc
}
if ! toolchain_ok; then
    pkgs="clang libclang-rt-dev"
    if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
        echo "fuzz: clang with libFuzzer is missing; run as root: apt-get install -y $pkgs" >&2
        exit 1
    fi
    echo "fuzz: installing $pkgs" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq >/dev/null
    apt-get install -y -qq --no-install-recommends $pkgs >/dev/null ||
        apt-get install -y -qq --no-install-recommends clang libclang-rt-14-dev >/dev/null
    toolchain_ok || { echo "fuzz: $cc still cannot link a libFuzzer target" >&2; exit 1; }
fi
make --no-print-directory fuzz-build FUZZ_CC="$cc" >"$out.build.log" 2>&1 ||
    { tail -n 30 "$out.build.log" >&2; echo "fuzz: the build failed" >&2; exit 1; }

export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for t in readers ops; do
    mkdir -p "$out/corpus-$t" "$out/artifacts"
    rm -f "$out/artifacts/$t-"*
    case $t in readers) len=4096 ;; *) len=1024 ;; esac
    "$out/fuzz_$t" -max_total_time="$secs" -print_final_stats=1 -max_len="$len" -timeout=30 \
        -rss_limit_mb=4096 -artifact_prefix="$out/artifacts/$t-" "$out/corpus-$t" "tests/fuzz-corpus/$t" \
        >"$out/$t.log" 2>&1 &
    eval "pid_$t=\$!"
done
total=0
crashes=0
for t in readers ops; do
    eval "wait \$pid_$t"
    rc=$?
    n=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$out/$t.log" | tail -n 1)
    [ -n "$n" ] || n=$(sed -n 's/^#\([0-9][0-9]*\).*/\1/p' "$out/$t.log" | tail -n 1)
    [ -n "$n" ] || n=0
    c=0
    for a in "$out/artifacts/$t-"*; do
        [ -f "$a" ] || continue
        c=$((c + 1))
        cp "$a" "tests/fuzz-corpus/$t/$(basename "$a" | sed "s/^$t-//")"
        echo "fuzz: $t: $(basename "$a") copied to tests/fuzz-corpus/$t/ (a regression test of make test)" >&2
    done
    if [ $c -eq 0 ] && [ $rc -ne 0 ]; then
        c=1
        echo "fuzz: $t exited with status $rc and left no input; see $out/$t.log" >&2
    fi
    [ $c -eq 0 ] || tail -n 40 "$out/$t.log" >&2
    echo "fuzz: $t: $n executions, $c crashes, corpus $(ls "$out/corpus-$t" | wc -l) inputs ($out/$t.log)"
    total=$((total + n))
    crashes=$((crashes + c))
done
echo "fuzz: $total executions, $crashes crashes"
[ $crashes -eq 0 ]
